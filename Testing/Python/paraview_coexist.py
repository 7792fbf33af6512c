"""pvbatch: the Anatomesh plugin leaves stock ParaView as it was. Every proxy ParaView defines
before the plugin is loaded keeps its VTK class and label afterwards (ImageReader and MeshQuality
used to be replaced), no filter or source label of ours equals a stock one (paraview.simple's
Tetrahedralize() and MeshQuality() stay ParaView's), and ours are reachable under their own
names."""
import os
import sys

from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403

PLUGIN = os.environ["ANATOMESH_PLUGIN"]
GROUPS = ("sources", "filters", "writers")


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def definitions():
    """{(group, name): (VTK class, label)} of every proxy ParaView defines now."""
    pxm = sm.ProxyManager().SMProxyManager
    table = {}
    for group in GROUPS:
        it = pxm.GetProxyDefinitionManager().NewSingleGroupIterator(group)
        it.GoToFirstItem()
        while not it.IsDoneWithTraversal():
            name = it.GetProxyName()
            proto = pxm.GetPrototypeProxy(group, name)
            table[(group, name)] = (proto.GetVTKClassName(), proto.GetXMLLabel()) if proto else (None, None)
            it.GoToNextItem()
    return table


stock = definitions()
if ("filters", "MeshQuality") not in stock or ("sources", "ImageReader") not in stock:
    fail("stock ParaView has no MeshQuality filter or ImageReader source: the check would prove nothing")
LoadPlugin(PLUGIN, remote=False, ns=globals())
after = definitions()

replaced = [(key, stock[key], after.get(key)) for key in stock if after.get(key) != stock[key]]
if replaced:
    fail("stock proxies replaced or removed: %s" % replaced)
ours = {key: value for key, value in after.items() if key not in stock}
if len(ours) < 20:
    fail("only %d Anatomesh proxies registered" % len(ours))
for key, (cls, label) in ours.items():
    if not key[1].startswith("Anatomesh"):
        fail("proxy %s/%s has no Anatomesh prefix" % key)
    if not cls.startswith("am"):
        fail("proxy %s/%s has the class %s" % (key[0], key[1], cls))
stock_labels = {(group, label) for (group, _), (_, label) in stock.items()}
clashes = [(key, label) for key, (_, label) in ours.items() if key[0] != "writers" and (key[0], label) in stock_labels]
if clashes:
    fail("labels that shadow stock ones: %s" % clashes)

# paraview.simple: the stock names still make the stock filters; ours have their own.
sphere = Sphere()
if Tetrahedralize(Input=sphere).GetXMLName() != "DataSetTriangleFilter":
    fail("Tetrahedralize() no longer makes ParaView's filter")
if MeshQuality(Input=sphere).GetXMLName() != "MeshQuality":
    fail("MeshQuality() no longer makes ParaView's filter")
ours_tet = AnatomeshTetrahedralize(Input=sphere)
if ours_tet.SMProxy.GetVTKClassName() != "amTetrahedralize":
    fail("AnatomeshTetrahedralize() makes %s" % ours_tet.SMProxy.GetVTKClassName())
if AnatomeshMeshQuality(Input=sphere).SMProxy.GetVTKClassName() != "amMeshQuality":
    fail("AnatomeshMeshQuality() is not Anatomesh's")
# Every paraview.simple name docs/filters.md gives exists and makes that proxy's class.
import re  # noqa: E402
source = os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
with open(os.path.join(source, "docs", "filters.md")) as f:
    documented = re.findall(r"class `(am[A-Za-z]+)`\)\n\nPipeline type `[A-Za-z]+`; ParaView proxy `[A-Za-z]+`, in "
                            r"`paraview.simple` `([A-Za-z0-9_]+)\(\)`", f.read())
if len(documented) < 30:
    fail("docs/filters.md names %d paraview.simple functions" % len(documented))
for cls, name in documented:
    if name not in globals():
        fail("docs/filters.md's %s() is not in paraview.simple" % name)
print("coexistence OK: %d stock proxies unchanged, %d Anatomesh proxies, %d documented names" % (
    len(stock), len(ours), len(documented)))
