"""``anatomesh run --report`` and ``anatomesh report``: report.html beside a run's outputs with its
pictures (the 3-D views rendered off-screen by VTK under an Xvfb the report starts itself, the
charts by matplotlib) and tables; without any X display, the charts and tables still, and a note."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

SOURCE = os.path.abspath(os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())
CLI = [sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh")]
VIEWS = ["mesh.png", "surface.png", "activation.png", "repolarisation.png", "body_surface.png"]
CHARTS = ["quality.png", "ecg.png"]


def run(*args, env=None):
    p = subprocess.run(CLI + list(args), capture_output=True, text=True, timeout=900, env=env)
    return p.returncode, p.stdout, p.stderr


def pixels(path):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3]
    return width, height, rgb


class Report(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = os.path.join(TMP, "report_job")
        shutil.rmtree(cls.out, ignore_errors=True)
        env = dict(os.environ)
        env.pop("DISPLAY", None)  # as on a server or in CI: the report starts its own Xvfb
        cls.result = run("run", os.path.join(SOURCE, "Examples", "Pipelines", "thorax.xml"), "--output", cls.out,
                         "--set", "spacing=4", "--set", "tolerance=1.5", "--set", "size=10", "--report", env=env)

    def test_run_writes_the_report_with_every_picture(self):
        code, stdout, stderr = self.result
        self.assertEqual(code, 0, stderr)
        self.assertIn("Report: %s" % os.path.join(self.out, "report.html"), stdout)
        self.assertNotIn("report:", stderr)  # no picture missing
        with open(os.path.join(self.out, "report.html")) as f:
            page = f.read()
        for name in VIEWS + CHARTS:
            path = os.path.join(self.out, "report", name)
            self.assertIn("src='report/%s'" % name, page)
            self.assertTrue(os.path.isfile(path), name)
            self.assertGreater(os.path.getsize(path), 10000, name)
            self.assertLess(os.path.getsize(path), 5000000, name)
            width, height, rgb = pixels(path)
            self.assertGreaterEqual(width, 700, name)
            self.assertGreaterEqual(height, 400, name)
            drawn = np.any(rgb < 245, axis=1).mean()  # not a blank page
            self.assertGreater(drawn, 0.05, name)
            if name in VIEWS:
                self.assertEqual((width, height), (1100, 720), name)
                self.assertGreater(len(np.unique(rgb, axis=0)), 200, name)  # shaded colour maps, not flat
        # The mesh view shows every region in its own colour, the legend names them.
        from anatomesh.report import scenes
        _, _, rgb = pixels(os.path.join(self.out, "report", "mesh.png"))
        colours = {tuple(int(round(255 * c)) for c in rgb_) for rgb_ in scenes.PALETTE[:10]}
        self.assertGreaterEqual(len(colours & {tuple(p) for p in np.unique(rgb, axis=0).tolist()}), 10)
        # Tables: the paper's Table 1 beside ours, region names, volumes (each organ beside an adult's),
        # interface distances.
        for text in ("Quality per region (the paper&#x27;s Table 1)", "paper (whole mesh)", "47.9", "5 Myocardium",
                     "Region volumes", "adult range (cm3)", "1000-4000", "Largest distance to the input per interface",
                     "whole mesh",
                     "Pipeline variables"):
            self.assertIn(text, page)
        self.assertEqual([f for f in os.listdir(os.path.join(self.out, "report")) if ".tmp" in f], [])

    def copy_of_the_run(self, name):
        """The run's folder copied elsewhere, without its report."""
        code, _, stderr = self.result
        self.assertEqual(code, 0, stderr)
        copy = os.path.join(TMP, name)
        shutil.rmtree(copy, ignore_errors=True)
        shutil.copytree(self.out, copy, ignore=shutil.ignore_patterns("report*"))
        return copy

    @staticmethod
    def without_x():
        """An environment with no display and no Xvfb to start (the command runs as python3 SCRIPT)."""
        env = dict(os.environ)
        env.pop("DISPLAY", None)
        env["PATH"] = os.path.join(TMP, "report_empty_path")
        os.makedirs(env["PATH"], exist_ok=True)
        return env

    def test_report_of_a_moved_folder_without_any_display(self):
        moved = self.copy_of_the_run("report_job_moved")
        code, stdout, stderr = run("report", moved, "--time", "100", env=self.without_x())
        self.assertEqual(code, 0, stderr)
        self.assertIn("3-D pictures not drawn: no X display", stderr)
        with open(os.path.join(moved, "report.html")) as f:
            page = f.read()
        self.assertIn("3-D pictures not drawn", page)
        for name in CHARTS:  # found where the moved folder holds them, not where the run wrote them
            self.assertTrue(os.path.isfile(os.path.join(moved, "report", name)), name)
        for name in VIEWS:
            self.assertFalse(os.path.exists(os.path.join(moved, "report", name)), name)
        self.assertIn("5 Myocardium", page)

    def test_report_names_the_outputs_it_cannot_read(self):
        broken = self.copy_of_the_run("report_job_broken")
        mesh = os.path.join(broken, "thorax_tets.vtu")
        with open(mesh, "r+b") as f:  # truncated mid-file
            f.truncate(os.path.getsize(mesh) // 3)
        with open(os.path.join(broken, "thorax_quality.csv"), "a") as f:
            f.write("not,a,row\n")
        code, stdout, stderr = run("report", broken, env=self.without_x())
        self.assertEqual(code, 0, stderr)
        self.assertIn("report: %s cannot be read" % mesh, stderr)
        self.assertIn("thorax_quality.csv cannot be read", stderr)
        with open(os.path.join(broken, "report.html")) as f:
            page = f.read()
        self.assertIn("thorax_tets.vtu cannot be read", page)
        self.assertNotIn("Region volumes", page)  # the mesh's table needs the mesh
        self.assertTrue(os.path.isfile(os.path.join(broken, "report", "ecg.png")))

    def test_report_of_what_is_not_a_run(self):
        code, _, stderr = run("report", os.path.join(TMP, "no_such_run_folder"))
        self.assertEqual(code, 1)
        self.assertIn("no_such_run_folder: not a folder", stderr)
        empty = os.path.join(TMP, "report_empty_folder")
        shutil.rmtree(empty, ignore_errors=True)
        os.makedirs(empty)
        code, _, stderr = run("report", empty)
        self.assertEqual(code, 0, stderr)
        self.assertIn("no anatomesh-run.json", stderr)
        self.assertIn("holds no mesh, surface", stderr)
        code, _, stderr = run("report", empty, "--time", "nan")
        self.assertEqual(code, 2)
        self.assertIn("must be a number of ms", stderr)


if __name__ == "__main__":
    unittest.main()
