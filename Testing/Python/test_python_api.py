"""The anatomesh Python package: wrapped filters in a plain VTK pipeline, checked by numbers."""
import os
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import anatomesh

TMP = os.environ.get("ANATOMESH_TEST_TMP", "/tmp")


def labels_of(image):
    return vtk_to_numpy(image.GetPointData().GetScalars())


class ExplicitExports(unittest.TestCase):
    """The package names every wrapped filter in __all__ (so IDEs and linters see them) and its one
    function, and no more."""

    def test_all_lists_every_wrapped_class(self):
        import importlib
        import pkgutil
        here = os.path.dirname(anatomesh.__file__)
        wrapped = set()
        for info in pkgutil.iter_modules([here]):
            if info.name.startswith("Anatomesh"):
                module = importlib.import_module("anatomesh." + info.name)
                wrapped |= {n for n in dir(module) if n.startswith("am")}
        self.assertEqual(set(anatomesh.__all__), wrapped | {"keep_freed_memory"})
        for name in anatomesh.__all__:
            self.assertTrue(callable(getattr(anatomesh, name)), name)


class KeepFreedMemory(unittest.TestCase):
    """anatomesh.keep_freed_memory() in a fresh interpreter without GLIBC_TUNABLES: a large block
    freed stays with the process for the next one (glibc's default maps it afresh and hands it
    back); with GLIBC_TUNABLES set it leaves the allocator as it is."""

    PROBE = """
import ctypes, sys
import anatomesh
libc = ctypes.CDLL(None)
libc.malloc.restype = ctypes.c_void_p
libc.malloc.argtypes = (ctypes.c_size_t,)
libc.free.argtypes = (ctypes.c_void_p,)
def resident():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096
kept = anatomesh.keep_freed_memory() if sys.argv[1] == "1" else False
size = 256 << 20
block = libc.malloc(size)
ctypes.memset(block, 1, size)
before = resident()
libc.free(block)
print(kept, (before - resident()) >> 20)
"""

    def probe(self, call, tunables=None):
        import subprocess
        import sys
        env = {k: v for k, v in os.environ.items() if k != "GLIBC_TUNABLES"}
        if tunables is not None:
            env["GLIBC_TUNABLES"] = tunables
        out = subprocess.run([sys.executable, "-c", self.PROBE, "1" if call else "0"], env=env, capture_output=True,
                             text=True, check=True).stdout.split()
        return out[0] == "True", int(out[1])

    @unittest.skipUnless(os.path.exists("/proc/self/statm") and hasattr(os, "confstr")
                         and "glibc" in (os.confstr("CS_GNU_LIBC_VERSION") or "").lower(), "glibc on Linux only")
    def test_freed_block_stays(self):
        kept, returned = self.probe(False)
        self.assertFalse(kept)
        self.assertGreater(returned, 200)  # glibc's default: the 256 MB go back to the kernel
        kept, returned = self.probe(True)
        self.assertTrue(kept)
        self.assertLess(returned, 16)  # kept for the next block
        kept, returned = self.probe(True, tunables="glibc.malloc.mmap_max=65536")
        self.assertFalse(kept)  # the user's own setting stays
        self.assertGreater(returned, 200)


class SyntheticAtlasFromPython(unittest.TestCase):
    def test_many_labels_int16(self):
        src = anatomesh.amSyntheticAtlasSource()
        src.SetNumberOfLabels(200)
        src.SetDimensions(48, 40, 32)
        src.SetSpacing(1.0, 1.0, 1.5)
        src.Update()
        image = src.GetOutputDataObject(0)
        labels = labels_of(image)
        self.assertEqual(labels.dtype, np.int16)
        self.assertEqual(len(np.unique(labels)), 201)  # outside and 200 cells
        self.assertEqual(image.GetSpacing(), (1.0, 1.0, 1.5))
        self.assertEqual(image.GetFieldData().GetArray("Seeds").GetNumberOfTuples(), 200)
        # Sheets between the cells take label 201 (the smallest cells can vanish under them).
        src.SetSheetWidth(1.0)
        src.Update()
        labels = labels_of(src.GetOutputDataObject(0))
        self.assertIn(201, labels)
        self.assertGreater(len(np.unique(labels)), 180)


class PhantomFromPython(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.src = anatomesh.amThoraxPhantomSource()
        cls.src.SetSpacing(2, 2, 2)
        cls.src.Update()

    def test_outputs(self):
        ct, labels = self.src.GetOutputDataObject(0), self.src.GetOutputDataObject(1)
        self.assertEqual(ct.GetDimensions(), (160, 120, 105))
        self.assertEqual(labels.GetPointData().GetScalars().GetName(), "Labels")
        counts = np.bincount(labels_of(labels), minlength=11)
        self.assertTrue((counts > 0).all(), counts)

    def test_volumes_close_to_analytic(self):
        counts = np.bincount(labels_of(self.src.GetOutputDataObject(1)), minlength=11)
        voxel = 8.0
        for label in (2, 5, 6, 7, 8):
            exact = self.src.GetExactVolume(label)
            self.assertAlmostEqual(counts[label] * voxel / exact, 1.0, delta=0.03,
                                   msg=self.src.GetLabelName(label))
        self.assertAlmostEqual(counts[1:].sum() * voxel / self.src.GetBodyVolume(), 1.0, delta=0.005)

    def test_ground_truth_queries(self):
        centre = [0.0, 0.0, 0.0]
        self.src.GetOrganCenter(6, centre)
        self.assertEqual(self.src.GetLabelAtPoint(*centre), 6)
        self.assertEqual(self.src.GetLabelName(6), "LeftVentricleBlood")

    def test_write_and_read_back(self):
        path = os.path.join(TMP, "py_labels.nii.gz")
        writer = anatomesh.amImageWriter()
        writer.SetInputConnection(self.src.GetOutputPort(1))
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        reader = anatomesh.amImageReader()
        reader.SetFileName(path)
        reader.Update()
        back = reader.GetOutput()
        self.assertEqual(back.GetDimensions(), (160, 120, 105))
        np.testing.assert_array_equal(labels_of(back), labels_of(self.src.GetOutputDataObject(1)))

    def test_the_ventricles_heart_from_python(self):
        heart = anatomesh.amThoraxPhantomSource()
        heart.SetSpacing(2, 2, 2)
        heart.SetHeartShape(anatomesh.amThoraxPhantomSource.VENTRICLES)
        for label in (5, 6, 7):
            centre = [0.0, 0.0, 0.0]
            heart.GetOrganCenter(label, centre)
            self.assertEqual(heart.GetLabelAtPoint(*centre), label)
        self.assertAlmostEqual(heart.GetExactVolume(6) / 1000.0, 89.6, delta=0.1)  # mL: the LV's cavity
        self.assertLess(heart.GetExactVolume(5), 0)  # the muscle round the RV's crescent: not closed-form

    def test_clicked_chambers_share_their_contrast_by_the_nearest_click(self):
        # A ventricle and its atrium (two balls of one contrast joined by an opening), a click in
        # each: each keeps its own chamber; by precedence alone the first takes both.
        from vtkmodules.util.numpy_support import numpy_to_vtk
        from vtkmodules.vtkCommonDataModel import vtkImageData
        z, y, x = np.mgrid[-20:21, -20:21, -35:36].astype(float)
        ventricle = (x + 14) ** 2 + y ** 2 + z ** 2 <= 144
        atrium = (x - 14) ** 2 + y ** 2 + z ** 2 <= 144
        opening = (np.abs(x) < 14) & (y ** 2 + z ** 2 <= 36)
        hu = np.where(ventricle | atrium | opening, 300.0, 40.0).astype(np.float32)
        image = vtkImageData()
        image.SetDimensions(71, 41, 41)
        image.SetOrigin(-35, -20, -20)
        image.GetPointData().SetScalars(numpy_to_vtk(hu.ravel(), deep=1))
        found = {}
        for compete in (True, False):
            snake = anatomesh.amSnakeSegmentation()
            self.assertTrue(snake.GetSeedsCompete())  # the default
            snake.SetSeedsCompete(compete)
            snake.SetInputData(image)
            snake.AddSeed(-14, 0, 0, 6)
            snake.AddSeed(14, 0, 0, 11)
            snake.Update()
            found[compete] = vtk_to_numpy(snake.GetOutput().GetPointData().GetScalars()).reshape(hu.shape)
        dice = lambda a, b: 2.0 * (a & b).sum() / (a.sum() + b.sum())
        self.assertGreater(dice(found[True] == 6, ventricle), 0.95)
        self.assertGreater(dice(found[True] == 11, atrium), 0.95)
        self.assertLess(dice(found[False] == 11, atrium), 0.01)

    def test_a_windowed_scan_carries_its_window(self):
        # The phantom's CT stored as a scan exported for viewing: 8 bits through a 600/300 window.
        from vtkmodules.util.numpy_support import numpy_to_vtk
        from vtkmodules.vtkCommonDataModel import vtkImageData
        ct = self.src.GetOutputDataObject(0)
        units = np.clip(np.round(vtk_to_numpy(ct.GetPointData().GetScalars()) * 255.0 / 600.0), 0, 255)
        image = vtkImageData()
        image.CopyStructure(ct)
        image.GetPointData().SetScalars(numpy_to_vtk(units.astype(np.uint8), deep=1))
        path = os.path.join(TMP, "py_windowed.nii.gz")
        writer = anatomesh.amImageWriter()
        writer.SetInputData(image)
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        reader = anatomesh.amImageReader()
        reader.SetFileName(path)
        reader.SetIntensityWindow(600, 300)
        reader.Update()
        window = reader.GetOutput().GetFieldData().GetArray("IntensityWindow")
        self.assertEqual(window.GetTuple2(0), (600.0, 300.0))
        # A window stated for a scan in HU is refused, naming the file.
        errors = []
        hu = anatomesh.amImageReader()
        hu.AddObserver("ErrorEvent", lambda obj, event: errors.append(obj.GetClassName()))
        writer.SetInputData(ct)
        path = os.path.join(TMP, "py_hu.nii.gz")
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        hu.SetFileName(path)
        hu.SetIntensityWindow(600, 300)
        hu.Update()
        self.assertTrue(errors)
        self.assertEqual(hu.GetOutput().GetNumberOfPoints(), 0)

    def test_time_series_on_worker_threads(self):
        """A time series queued on amConcurrentXMLWriter: every frame readable, with its own values."""
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        from vtkmodules.vtkCommonDataModel import vtkImageData
        files = anatomesh.amConcurrentXMLWriter()
        self.assertEqual(files.GetNumberOfThreads(), 2)
        frame = vtkImageData()
        frame.ShallowCopy(self.src.GetOutputDataObject(0))
        ct = vtk_to_numpy(frame.GetPointData().GetScalars())
        paths = [os.path.join(TMP, "py_series_%d.vti" % k) for k in range(4)]
        for path in paths:
            self.assertTrue(files.Write(frame, path), files.GetErrorMessage())
        self.assertTrue(files.Finish(), files.GetErrorMessage())
        for path in paths:
            reader = vtkXMLImageDataReader()
            reader.SetFileName(path)
            reader.Update()
            np.testing.assert_array_equal(vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()), ct)
        self.assertFalse(files.Write(frame, os.path.join(TMP, "no_such_folder", "frame.vti")) and files.Finish())
        self.assertIn("no_such_folder", files.GetErrorMessage())


if __name__ == "__main__":
    unittest.main()


class ReadmeExample(unittest.TestCase):
    """The README's Python example runs as it is written and prints what its last comment says."""

    def test_the_readme_example_prints_what_it_says(self):
        import contextlib
        import io
        import re
        source = os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
        with open(os.path.join(source, "README.md")) as f:
            code = re.search(r"```python\n(.*?)```", f.read(), re.S).group(1)
        claimed = re.search(r"# (\d+) triangles .*Hausdorff ([\d.]+) mm", code)
        self.assertIsNotNone(claimed, "the example's last comment gives its triangles and Hausdorff distance")
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            exec(compile(code, "README.md", "exec"), {})
        got = re.search(r"(\d+) triangles, Hausdorff ([\d.]+) mm", printed.getvalue())
        self.assertIsNotNone(got, printed.getvalue())
        self.assertEqual(int(got.group(1)), int(claimed.group(1)))
        self.assertAlmostEqual(float(got.group(2)), float(claimed.group(2)), places=5)
