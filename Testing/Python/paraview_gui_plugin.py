"""Run inside the stock ParaView GUI (xvfb-run paraview --script=... --exit): the installed
Anatomesh plugin is listed by the plugin manager (as in Tools > Manage Plugins), loads, and its
phantom source produces the expected label map. Prints "GUI plugin check OK" on success."""
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

pm = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager()
info = pm.GetLocalInformation()
listed = {info.GetPluginName(i): info.GetPluginFileName(i) for i in range(info.GetNumberOfPlugins())}
if "Anatomesh" not in listed:
    print("GUI plugin check FAILED: Anatomesh not listed; listed: %s" % sorted(listed))
else:
    LoadPlugin(listed["Anatomesh"], remote=False, ns=globals())
    src = ThoraxPhantomSource()
    src.Spacing = [8.0, 8.0, 8.0]
    src.UpdatePipeline()
    rng = OutputPort(src, 1).PointData["Labels"].GetRange()
    Show(OutputPort(src, 0))
    Render()
    if tuple(rng) == (0.0, 10.0):
        print("GUI plugin check OK: %s" % listed["Anatomesh"])
    else:
        print("GUI plugin check FAILED: label range %s" % (rng,))
