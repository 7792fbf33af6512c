"""pvbatch: load the Anatomesh plugin, build a pipeline, save a .pvsm state, reload it in a fresh
pvbatch process, and check that the proxies exist with their properties and produce the same
numbers. (LoadState without the plugin only logs and drops the proxy, hence the explicit checks.)"""
import os
import subprocess
import sys

from paraview.simple import *  # noqa: F401,F403

PLUGIN = os.environ["ANATOMESH_PLUGIN"]
TMP = os.environ.get("ANATOMESH_TEST_TMP", "/tmp")
STATE = os.path.join(TMP, "anatomesh_state.pvsm")


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def numbers(source):
    source.UpdatePipeline()
    labels = OutputPort(source, 1)
    info = labels.GetDataInformation()
    rng = labels.PointData["Labels"].GetRange()
    return info.GetNumberOfPoints(), tuple(rng)


LoadPlugin(PLUGIN, remote=False, ns=globals())

if len(sys.argv) > 1 and sys.argv[1] == "--reload":
    LoadState(STATE)
    src = FindSource("Phantom")
    if src is None:
        fail("the state did not recreate the ThoraxPhantomSource proxy")
    if list(src.Spacing) != [6.0, 6.0, 6.0] or src.Seed != 3:
        fail("properties not restored: Spacing=%s Seed=%s" % (list(src.Spacing), src.Seed))
    got = numbers(src)
    expected = tuple(float(x) for x in sys.argv[2].split(","))
    if (float(got[0]),) + got[1] != expected:
        fail("reloaded numbers %s differ from %s" % (got, expected))
    snake = FindSource("Snake")
    if snake is None or list(snake.Seeds) != [72.0, 5.0, 5.0, 4.0]:
        fail("the snake segmentation or its seeds were not restored")
    snake.UpdatePipeline()
    if tuple(snake.PointData["Labels"].GetRange()) != (0.0, 4.0):
        fail("reloaded snake output range %s" % (snake.PointData["Labels"].GetRange(),))
    print("reloaded state OK:", got)
    sys.exit(0)

src = ThoraxPhantomSource(registrationName="Phantom")
src.Spacing = [6.0, 6.0, 6.0]
src.Seed = 3
n, rng = numbers(src)
if n != 53 * 40 * 35 or rng != (0.0, 10.0):
    fail("unexpected phantom output: %d points, label range %s" % (n, rng))
reader_ok = "AnatomeshImageReader" in globals() and "MeditMeshReader" in globals()
if not reader_ok:
    fail("the plugin does not expose AnatomeshImageReader/MeditMeshReader")
# The segmentation with a repeatable property (x y z label seeds) through ParaView's proxies.
snake = SnakeSegmentation(registrationName="Snake", Input=OutputPort(src, 0))
snake.Seeds = [72.0, 5.0, 5.0, 4.0]
snake.UpdatePipeline()
if tuple(snake.PointData["Labels"].GetRange()) != (0.0, 4.0):
    fail("snake output range %s" % (snake.PointData["Labels"].GetRange(),))
SaveState(STATE)
child = subprocess.run([os.environ.get("PVBATCH", "pvbatch"), "--force-offscreen-rendering", __file__, "--reload",
                        "%d,%s,%s" % (n, rng[0], rng[1])], capture_output=True, text=True, timeout=300)
print(child.stdout, child.stderr)
if child.returncode != 0 or "reloaded state OK" not in child.stdout:
    fail("the fresh process could not reload the state")
print("plugin state round trip OK")
