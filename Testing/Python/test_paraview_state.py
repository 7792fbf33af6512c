"""``anatomesh state``: a ParaView state holding Anatomesh proxies loads with the plugin and updates
every source; one that needs a proxy the plugin does not define, a plugin ParaView cannot load, or a
file that is not a state, is an error (exit 1) naming the plugin or the problem — where ParaView's own
LoadState drops the proxies and exits 0."""
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap
import unittest

SOURCE = os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())
CLI = [sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh")]
PVBATCH = os.environ.get("PVBATCH") or shutil.which("pvbatch")

SAVE = """
import sys
from paraview.simple import *
LoadPlugin(sys.argv[1], remote=False, ns=globals())
src = ThoraxPhantomSource(registrationName="Phantom")
src.Spacing = [8.0, 8.0, 8.0]
surface = LabelSurface(registrationName="Surface", Input=OutputPort(src, 1))
SaveState(sys.argv[2])
"""


@unittest.skipUnless(PVBATCH and os.environ.get("ANATOMESH_PLUGIN"), "needs pvbatch and the plugin built here")
class StateCommand(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="state_", dir=TMP)
        cls.saved = os.path.join(cls.dir, "saved.pvsm")
        script = os.path.join(cls.dir, "save.py")
        with open(script, "w") as f:
            f.write(textwrap.dedent(SAVE))
        subprocess.run([PVBATCH, "--force-offscreen-rendering", script, os.environ["ANATOMESH_PLUGIN"], cls.saved],
                       check=True, capture_output=True, timeout=300)
        with open(cls.saved) as f:
            cls.text = f.read()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def state(self, *args):
        return subprocess.run(CLI + ["state"] + list(args), capture_output=True, text=True, timeout=300)

    def variant(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_the_saved_state_loads_and_updates_every_source(self):
        done = self.state(self.saved)
        self.assertEqual(done.returncode, 0, done.stderr)
        # 40 x 30 x 26 voxels: the state kept the 8 mm spacing.
        self.assertIn("Phantom (AnatomeshThoraxPhantomSource): 31200 points", done.stdout)
        self.assertRegex(done.stdout, r"Surface \(AnatomeshLabelSurface\): [1-9]\d* points, [1-9]\d* cells")

    def test_a_proxy_the_plugin_does_not_define_is_named(self):
        path = self.variant("newer.pvsm", self.text.replace('"AnatomeshLabelSurface"', '"AnatomeshLabelSurfaceV9"'))
        done = self.state(path)
        self.assertEqual(done.returncode, 1)
        self.assertIn("needs AnatomeshLabelSurfaceV9, which the Anatomesh plugin", done.stderr)
        self.assertNotIn("Traceback", done.stderr)

    def test_a_plugin_paraview_cannot_load_is_named(self):
        done = self.state("--plugin", os.path.join(self.dir, "missing", "Anatomesh.so"), self.saved)
        self.assertEqual(done.returncode, 1)
        self.assertIn("needs the Anatomesh ParaView plugin for 2 proxy type(s)", done.stderr)
        self.assertIn("AnatomeshThoraxPhantomSource", done.stderr)

    def test_what_is_not_a_state_is_named(self):
        for name, text, words in (("other.pvsm", "<Pipeline/>", "no ServerManagerState"),
                                  ("cut.pvsm", self.text[: len(self.text) // 2], "not a ParaView state")):
            done = self.state(self.variant(name, text))
            self.assertEqual(done.returncode, 1, name)
            self.assertIn(name + ": ", done.stderr)
            self.assertIn(words, done.stderr)
        done = self.state(os.path.join(self.dir, "absent.pvsm"))
        self.assertEqual(done.returncode, 1)
        self.assertIn("absent.pvsm: No such file", done.stderr)


if __name__ == "__main__":
    unittest.main()
