"""Run inside the stock ParaView GUI (xvfb-run paraview --script=... --exit) with the plugin built
here: Seed Points shows its seeds as handles in the view (the Seeds panel's widget) over the
phantom's CT, Snake Segmentation takes them on its SeedPoints input and segments the organs they
mark, and the view is saved as a picture (the documentation's screenshot). Prints "GUI seeds check
OK" on success."""
import ctypes
import os
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403


def process_gui_events(seconds=2.0):
    """Let the GUI's event loop run for a while (a --script runs inside one Qt event): the
    properties panel shows the active source and its widget only once its queued events and
    timers have run. The GUI's Python has no Qt binding, so QCoreApplication::processEvents is
    called through ctypes."""
    qt = ctypes.CDLL("libQt5Core.so.5")
    process = qt._ZN16QCoreApplication13processEventsE6QFlagsIN10QEventLoop17ProcessEventsFlagEE
    process.argtypes = [ctypes.c_int]
    end = time.time() + seconds
    while time.time() < end:
        process(0)
        time.sleep(0.01)

out = os.path.join(os.environ.get("ANATOMESH_TEST_TMP", "."), "gui_seeds.png")
LoadPlugin(os.environ["ANATOMESH_PLUGIN"], remote=False, ns=globals())
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1000, 700]
phantom = ThoraxPhantomSource(Spacing=[3.0, 3.0, 3.0])
ct = Show(OutputPort(phantom, 0), view)
ct.SetRepresentationType("Slice")
ct.SliceMode = "XY Plane"
bounds = phantom.GetDataInformation().GetBounds()
ct.Slice = int(round((-28.0 - bounds[4]) / 3.0))  # the slice through the two ventricles' seeds
ColorBy(ct, ("POINTS", "CT"))
GetColorTransferFunction("CT").ApplyPreset("Grayscale", True)
GetColorTransferFunction("CT").RescaleTransferFunction(-300.0, 400.0)

seeds = SeedPoints()
shown = Show(seeds, view)
shown.SetRepresentationType("Points")
shown.PointSize = 14
shown.RenderPointsAsSpheres = 1
ColorBy(shown, ("POINTS", "Label"))
SetActiveSource(seeds)  # the properties panel shows it: its handles appear in the view
process_gui_events()
positions = list(seeds.Positions)
view.CameraPosition = [0.0, 0.0, 700.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
ResetCamera(view)
Render(view)
process_gui_events()
SaveScreenshot(out, view, ImageResolution=[1000, 700])

# Then the segmentation on them (after the picture: a filter made from a script takes the panel's
# focus away from the seeds, and their handles with it).
snake = SnakeSegmentation(Input=OutputPort(phantom, 0), SeedPoints=seeds)
snake.UpdatePipeline()
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
labels = sorted(set(vtk_to_numpy(servermanager.Fetch(snake).GetPointData().GetArray("Labels")).tolist()))
# The handles' poly-line widget is drawn (yellow) in the picture.
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
png = vtkPNGReader()
png.SetFileName(out)
png.Update()
rgb = vtk_to_numpy(png.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
widget_pixels = int(((rgb[:, 0] > 200) & (rgb[:, 1] > 200) & (rgb[:, 2] < 100)).sum())
if len(positions) == 12 and labels == [0, 6, 7, 8] and widget_pixels > 150:
    print("GUI seeds check OK: %s" % out)
else:
    print("GUI seeds check FAILED: positions %s, labels %s, widget pixels %d" % (positions, labels, widget_pixels))
