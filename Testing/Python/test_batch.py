"""``anatomesh batch``: a pipeline over the cases of a manifest, in parallel, resumable, one failure kept to its
case, a summary with every case's figures; and the same cases shared by two MPI ranks."""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

SOURCE = os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())
CLI = [sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh")]

PIPELINE = """
<AnatomeshPipeline version="1">
  <Variable name="spacing" default="8"/>
  <Variable name="noise" default="0"/>
  <Filter name="phantom" type="ThoraxPhantomSource">
    <Property name="Spacing" value="${spacing} ${spacing} ${spacing}"/>
    <Property name="NoiseStandardDeviation" value="${noise}"/>
  </Filter>
  <Filter name="surface" type="LabelSurface"><Input from="phantom" port="Labels"/></Filter>
  <Filter name="tets" type="Tetrahedralize"><Input from="surface"/></Filter>
  <Filter name="quality" type="MeshQuality"><Input from="tets" port="Mesh"/></Filter>
  <Output from="quality" port="Table" file="${output}/quality.csv"/>
  <Output from="quality" port="Mesh" file="${output}/mesh.vtu"/>
  <Filter name="save" type="ImageWriter">
    <Input from="phantom" port="Labels"/>
    <Property name="FileName" value="${output}/labels.nii.gz"/>
  </Filter>
</AnatomeshPipeline>
"""


def run(*args, env=None):
    p = subprocess.run(CLI + list(args), capture_output=True, text=True, timeout=600, env=env)
    return p.returncode, p.stdout, p.stderr


class Batch(unittest.TestCase):
    def setUp(self):
        self.dir = os.path.join(TMP, "batch_" + self._testMethodName)
        shutil.rmtree(self.dir, ignore_errors=True)
        os.makedirs(self.dir)
        self.pipeline = os.path.join(self.dir, "mesh.xml")
        with open(self.pipeline, "w") as f:
            f.write(textwrap.dedent(PIPELINE).lstrip())
        # Three cases; "broken" asks for a negative noise, which the phantom refuses.
        self.manifest = os.path.join(self.dir, "cases.csv")
        with open(self.manifest, "w") as f:
            f.write("case,spacing,noise\ncoarse,10,0\nbroken,8,-5\nfine,8,0\n")
        self.out = os.path.join(self.dir, "out")

    def summary(self):
        with open(os.path.join(self.out, "batch_summary.csv")) as f:
            return {row["case"]: row for row in csv.DictReader(f)}

    def test_cases_run_in_parallel_and_one_failure_stays_in_its_case(self):
        code, stdout, stderr = run("batch", self.pipeline, self.manifest, "--jobs", "2", "--output", self.out)
        self.assertEqual(code, 1, stderr)  # one case failed
        self.assertIn("3 cases: 2 complete, 0 skipped, 1 failed", stdout)
        rows = self.summary()
        self.assertEqual(rows["coarse"]["status"], "complete")
        self.assertEqual(rows["fine"]["status"], "complete")
        self.assertEqual(rows["broken"]["status"], "failed")
        self.assertIn("NoiseStandardDeviation", rows["broken"]["error"])
        # Each case: its outputs, its log, and the marker written last with its figures.
        for case in ("coarse", "fine"):
            folder = os.path.join(self.out, case)
            self.assertTrue(os.path.getsize(os.path.join(folder, "quality.csv")) > 0)
            with open(os.path.join(folder, "anatomesh-run.json")) as f:
                done = json.load(f)
            self.assertEqual(done["status"], "complete")
            self.assertIn("phantom", open(os.path.join(folder, "anatomesh.log")).read())
            self.assertGreater(float(rows[case]["quality.csv: tetrahedra"]), 100)
            self.assertGreater(float(rows[case]["labels.nii.gz: label 5 cm3"]), 300)
        self.assertGreater(float(rows["fine"]["quality.csv: tetrahedra"]),
                           float(rows["coarse"]["quality.csv: tetrahedra"]))
        with open(os.path.join(self.out, "broken", "anatomesh-run.json")) as f:
            self.assertEqual(json.load(f)["status"], "failed")
        html = open(os.path.join(self.out, "batch_summary.html")).read()
        self.assertIn("3 cases, 1 failed", html)
        # Every manifest variable, counts as integers, each case's folder and log linked.
        self.assertEqual((rows["coarse"]["spacing"], rows["broken"]["noise"]), ("10", "-5"))
        self.assertRegex(rows["fine"]["quality.csv: tetrahedra"], r"^\d+$")
        self.assertIn("<a href='coarse'>coarse</a>", html)
        self.assertIn("<a href='fine/anatomesh.log'>", html)

        # Resume: complete cases are skipped, the failed one runs again (and fails again); with --report the
        # skipped cases get their report, linked from the summary.
        code, stdout, stderr = run("batch", self.pipeline, self.manifest, "--resume", "--report", "--output", self.out)
        self.assertEqual(code, 1, stderr)
        self.assertIn("3 cases: 0 complete, 2 skipped, 1 failed", stdout)
        rows = self.summary()
        for case in ("coarse", "fine"):
            self.assertEqual(rows[case]["report"], os.path.join(self.out, case, "report.html"))
            page = open(rows[case]["report"]).read()
            self.assertIn("Quality per region", page)
            for picture in ("mesh.png", "quality.png"):
                self.assertTrue(os.path.isfile(os.path.join(self.out, case, "report", picture)), picture)
        self.assertEqual(rows["broken"]["report"], "")
        self.assertIn("<a href='coarse/report.html'>report</a>", open(os.path.join(self.out, "batch_summary.html")).read())
        # A changed variable is a new run, not a skip; the broken case mended runs too.
        with open(self.manifest, "w") as f:
            f.write("case,spacing,noise\ncoarse,12,0\nbroken,8,5\nfine,8,0\n")
        code, stdout, stderr = run("batch", self.pipeline, self.manifest, "--resume", "--output", self.out)
        self.assertEqual(code, 0, stderr)
        self.assertIn("3 cases: 2 complete, 1 skipped, 0 failed", stdout)
        self.assertEqual(self.summary()["fine"]["status"], "skipped (complete)")

    def test_sigterm_stops_every_case_and_writes_the_summary(self):
        # Three slow cases one at a time: SIGTERM while the first runs ends it (its whole process
        # group), starts neither of the others, and the summary says so; nothing is left running.
        with open(self.manifest, "w") as f:
            f.write("case,spacing,noise\nfirst,1.5,0\nsecond,1.5,0\nthird,1.5,0\n")
        batch = subprocess.Popen(CLI + ["batch", self.pipeline, self.manifest, "--jobs", "1", "--output", self.out],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
        log = os.path.join(self.out, "first", "anatomesh.log")
        deadline = time.time() + 120
        def started():
            if not os.path.exists(log):
                return False
            with open(log) as f:
                return "surface" in f.read()
        while time.time() < deadline and not started():
            time.sleep(0.2)
        os.kill(batch.pid, signal.SIGTERM)
        stdout, stderr = batch.communicate(timeout=60)
        self.assertEqual(batch.returncode, 128 + signal.SIGTERM, stderr)
        self.assertIn("3 cases: 0 complete, 0 skipped, 0 failed, 3 interrupted", stdout)
        rows = self.summary()
        self.assertEqual({r["status"] for r in rows.values()}, {"interrupted"})
        self.assertIn("signal 15", rows["first"]["error"])
        self.assertIn("not started", rows["third"]["error"])
        self.assertFalse(os.path.exists(os.path.join(self.out, "third")))
        # No case process outlives the batch.
        time.sleep(1)
        alive = []
        for pid in os.listdir("/proc"):
            try:
                with open("/proc/%s/cmdline" % pid, "rb") as f:
                    if self.out.encode() in f.read():
                        alive.append(pid)
            except OSError:
                pass
        self.assertEqual(alive, [])
        # --resume runs them again: no case is marked complete.
        marker = os.path.join(self.out, "first", "anatomesh-run.json")
        if os.path.exists(marker):
            with open(marker) as f:
                self.assertNotEqual(json.load(f).get("status"), "complete")

    def test_each_case_keeps_to_its_own_folder(self):
        # A case named '..' would write into the parent of --output; two rows with one output folder
        # would mix their files: both refused before anything runs.
        for rows, words in (("case,spacing\n..,10\n", "'..'"),
                            ("case,spacing,output\na,10,%s/same\n" % self.dir, "lies outside --output"),
                            ("case,spacing,output\na,10,../same\n", "lies outside --output"),
                            ("case,spacing,output\na,10,same\nb,10,same\n", "write into one folder"),
                            ("case,spacing,output\na,10,same\nb,10,same/inner\n", "write into one folder")):
            with open(self.manifest, "w") as f:
                f.write(rows)
            code, stdout, stderr = run("batch", self.pipeline, self.manifest, "--output", self.out)
            self.assertEqual(code, 2, stderr)
            self.assertIn(words, stderr)
            self.assertFalse(os.path.exists(os.path.join(self.dir, "labels.nii.gz")))
            self.assertFalse(os.path.exists(os.path.join(self.dir, "same")))

    def test_manifest_mistakes_name_the_line(self):
        bad = os.path.join(self.dir, "bad.csv")
        for text, needle in (("case,spacing,colour\na,8,red\n", "unknown: colour"),
                             ("case,spacing\na,8,9\n", "bad.csv:2: 3 values for 2 columns"),
                             ("case,spacing\na,8\na,9\n", "case name 'a' is repeated"),
                             ("spacing\n", "at least one case")):
            with open(bad, "w") as f:
                f.write(text)
            code, _, stderr = run("batch", self.pipeline, bad, "--output", self.out)
            self.assertEqual(code, 2)
            self.assertIn(needle, stderr)

    def test_two_mpi_ranks_share_the_cases(self):
        mpirun = shutil.which("mpirun")
        try:
            import mpi4py  # noqa: F401
        except ImportError:
            mpi4py = None
        if not mpirun or mpi4py is None:
            self.skipTest("mpirun or mpi4py is not installed")
        with open(self.manifest, "w") as f:
            f.write("case,spacing\na,10\nb,10\nc,12\nd,12\n")
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
        p = subprocess.run([mpirun, "-n", "2"] + CLI + ["batch", self.pipeline, self.manifest, "--output", self.out],
                           capture_output=True, text=True, timeout=600, env=env)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(p.stdout.count("4 cases: 4 complete"), 1)  # rank 0 alone sums up
        rows = self.summary()
        self.assertEqual(sorted(rows), ["a", "b", "c", "d"])
        self.assertTrue(all(r["status"] == "complete" for r in rows.values()))


if __name__ == "__main__":
    unittest.main()
