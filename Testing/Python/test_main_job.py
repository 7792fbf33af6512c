"""The main job as it ships (Examples/Pipelines/thorax.xml at its own 1 mm, through the ``anatomesh``
command): every organ segmented with Dice >= 0.98 (the 4-10 mm heart wall >= 0.93), the heartbeat on the segmented mesh agrees with the
same job run on the phantom's exact labels (the reference, made only here): activation times within
3 ms RMS at common points, every lead correlating >= 0.85 (a nearly null lead within 5 % RMS); its tetrahedra meet the README's figures; and
the ECG read as a cardiologist reads it meets the clinical targets (docs/limits.md says which it misses); FEniCSx loads its
mesh from the .msh and the .xdmf with their tags and solves on it. The paper's Table 1 case at its own 1 mm
(Examples/Pipelines/paper_table.xml) meets the bars the README gives it. Each figure the README quotes is
recorded (figures_record) for scripts/figures.py."""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

from figures_record import record
from simulation_agreement import AgreesWithTruth

SOURCE = os.path.abspath(os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())
JOB = os.path.join(SOURCE, "Examples", "Pipelines", "thorax.xml")


def run_job(pipeline, out):
    shutil.rmtree(out, ignore_errors=True)
    p = subprocess.run([sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh"), "run", pipeline, "--output",
                        out], capture_output=True, text=True, timeout=800)
    if p.returncode != 0:
        raise AssertionError("%s failed: %s" % (pipeline, p.stderr[-2000:]))


def truth_pipeline():
    """The main job with the surface made from the phantom's own labels instead of the segmentation."""
    with open(JOB) as f:
        text = f.read()
    head, tail = text.split('<Filter name="surface" type="LabelSurface">', 1)
    segmented, rest = tail.split("</Filter>", 1)
    assert '<Input from="segmentation"/>' in segmented, "thorax.xml's surface no longer reads the segmentation"
    truth = segmented.replace('<Input from="segmentation"/>', '<Input from="phantom" port="Labels"/>')
    text = head + '<Filter name="surface" type="LabelSurface">' + truth + "</Filter>" + rest
    # Nothing else reads the segmentation then: without its score and its file, the snake does not run.
    for pattern in (r'<Filter name="dice".*?</Filter>', r'<Output from="dice"[^>]*/>',
                    r'<Filter name="save_labels".*?</Filter>'):
        text, n = re.subn(pattern, "", text, count=1, flags=re.S)
        assert n == 1, "thorax.xml no longer has " + pattern
    path = os.path.join(TMP, "thorax_truth_reference.xml")
    with open(path, "w") as f:
        f.write(text)
    return path


def last_heart(out):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, "thorax_heart_0100.vtu"))
    reader.Update()
    return reader.GetOutput()


def leads(out):
    with open(os.path.join(out, "thorax_ecg.csv")) as f:
        rows = list(csv.reader(f))
    values = np.array(rows[1:], dtype=float)
    return {name.split("_")[0]: values[:, c] for c, name in enumerate(rows[0])}  # "I_mV": lead I


def run_figures(out):
    with open(os.path.join(out, "anatomesh-run.json")) as f:
        return json.load(f)


def whole_mesh_row(path):
    """The quality table's last row (Region -1: the whole mesh)."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows, next(r for r in rows if r["Region"] == "-1")


class MainJob(AgreesWithTruth, unittest.TestCase):
    # Deterministic outputs: the bars sit just past the README's figures (2.47 ms, 0.884 in V1, over the
    # RV's 4 mm free wall that the segmentation makes about 3 mm; aVL, 0.15 mV, by its RMS difference).
    activation_rms_bar = 3.0
    correlation_bar = 0.85
    null_lead_fraction = 0.25
    figure_prefix = "main_job"

    @classmethod
    def setUpClass(cls):
        cls.segmented_dir = os.path.join(TMP, "main_job_segmented")
        cls.truth_dir = os.path.join(TMP, "main_job_truth")
        run_job(JOB, cls.segmented_dir)
        run_job(truth_pipeline(), cls.truth_dir)
        cls.segmented = (last_heart(cls.segmented_dir), leads(cls.segmented_dir))
        cls.truth = (last_heart(cls.truth_dir), leads(cls.truth_dir))

    def test_the_ecg_reads_as_a_heartbeat(self):
        with open(os.path.join(self.segmented_dir, "thorax_ecg_features.csv")) as f:
            rows = {r["Lead"]: r for r in csv.DictReader(f)}
        figures = run_figures(self.segmented_dir)["figures"]["thorax_ecg_features.csv"]
        qrs, qt = figures["QRS ms"], figures["QT ms"]
        print("QRS %.0f ms, QT %.0f ms; R (mV) %s; T %s" % (
            qrs, qt, " ".join("%s %.2f" % (k, float(r["R_mV"])) for k, r in rows.items()),
            " ".join("%s %s" % (k, r["TPolarity"]) for k, r in rows.items())))
        # A healthy QT; the T wave upright where it is upright in a healthy heart, inverted in aVR.
        self.assertTrue(320 <= qt <= 460, qt)
        for lead in ("I", "II", "V5", "V6"):
            self.assertEqual(rows[lead]["TPolarity"], "upright", lead)
        self.assertEqual(rows["aVR"]["TPolarity"], "inverted")
        # A healthy QRS: 70-110 ms, R of a healthy size in the limb leads I and II (the axis points
        # down and left: II's R stands above its S), and rising from V1 through V4 to V5.
        R = {lead: float(r["R_mV"]) for lead, r in rows.items()}
        for lead in ("I", "II"):
            self.assertTrue(0.5 <= R[lead] <= 3.0, rows[lead])
        self.assertGreater(R["II"], -float(rows["II"]["S_mV"]))
        self.assertLess(R["V1"], R["V2"])
        self.assertLess(R["V2"], R["V4"])
        self.assertLess(R["V4"], R["V5"])
        self.assertTrue(70 <= qrs <= 110, qrs)
        upright = [lead for lead, r in rows.items() if r["TPolarity"] == "upright"]
        record(self, "main_job.qrs", qrs, "ms", [70, 110])
        record(self, "main_job.qt", qt, "ms", [320, 460])
        record(self, "main_job.t_upright", ", ".join(upright), "leads")
        record(self, "main_job.r_leads", " ".join("%s %.2f" % (k, R[k]) for k in ("I", "II", "V1", "V2", "V3", "V4",
                                                                                   "V5", "V6")), "mV")
        # The QRS as read spans the ventricles' activation (a QRS duration is the time the
        # depolarisation takes), within a few milliseconds.
        activation = vtk_to_numpy(self.segmented[0].GetPointData().GetArray("ActivationTime"))
        self.assertLess(abs(qrs - activation.max()), 8.0, (qrs, activation.max()))
        record(self, "main_job.activation", float(activation.max()), "ms")

    def test_every_organ_is_segmented(self):
        with open(os.path.join(self.segmented_dir, "thorax_dice.csv")) as f:
            rows = list(csv.DictReader(f))
        organs = [r for r in rows if int(r["Label"]) > 0]
        self.assertEqual([int(r["Label"]) for r in organs], list(range(1, 11)))
        dice = {int(r["Label"]): float(r["Dice"]) for r in organs}
        for label, value in dice.items():
            print("organ %2s Dice %.4f" % (label, value))
            # The README's figures are 0.946 (the myocardium: a wall 4-10 mm thick whose outer side
            # shows 10 HU of contrast under 20 HU of noise) and 0.984 (ribs) to 0.999.
            self.assertGreaterEqual(value, 0.93 if label == 5 else 0.98, label)
        record(self, "main_job.dice_lowest", min(dice.values()), "", 0.93)
        record(self, "main_job.dice_highest", max(dice.values()), "", 0.98)
        record(self, "main_job.dice_myocardium", dice[5], "", 0.93)
        record(self, "main_job.dice_ribs", dice[10], "", 0.98)

    def test_the_tetrahedra_meet_the_readmes_figures(self):
        # The README's figures: 0.93 M tetrahedra, mean Q 1.391, worst 6.74, every dihedral >= 10.03 degrees,
        # every organ within 0.99 % of its voxels; the bars just past them.
        rows, whole = whole_mesh_row(os.path.join(self.segmented_dir, "thorax_quality.csv"))
        figures = run_figures(self.segmented_dir)
        labels = figures["figures"]["thorax_labels.nii.gz"]
        off = max(abs(float(r["Volume_mm3"]) / 1000.0 / labels["label %s cm3" % r["Region"]] - 1.0)
                  for r in rows if r["Region"] != "-1")
        record(self, "main_job.tetrahedra", int(whole["ne"]), "")
        record(self, "main_job.mean_q", float(whole["MeanQuality"]), "", 1.40)
        record(self, "main_job.worst_q", float(whole["MaximumQuality"]), "", 7.5)
        record(self, "main_job.smallest_dihedral", float(whole["MinimumDihedralAngle_deg"]), "deg", 10.0)
        record(self, "main_job.volume_off", 100.0 * off, "%", 1.0)
        self.assertLessEqual(float(whole["MeanQuality"]), 1.40)
        self.assertLessEqual(float(whole["MaximumQuality"]), 7.5)
        self.assertGreaterEqual(float(whole["MinimumDihedralAngle_deg"]), 10.0)
        self.assertLessEqual(off, 0.01)
        # Its seconds on this machine (scripts/figures.py runs this test alone); not a bar.
        stages = figures["stage_seconds"]
        record(self, "main_job.seconds", figures["seconds"], "s")
        for stage, seconds in stages.items():
            record(self, "main_job.stage." + stage, seconds, "s")
        record(self, "main_job.heartbeat_seconds", stages["fibres"] + stages["heart"] + stages["ecg"], "s")

    def test_fenicsx_loads_the_main_jobs_mesh_and_solves_on_it(self):
        # The mesh files as the job writes them (0.93 M tetrahedra), through FEniCSx's own readers.
        probe = subprocess.run([sys.executable, "-c", "import dolfinx"], capture_output=True, text=True)
        if probe.returncode != 0:
            self.skipTest("python3-dolfinx is not installed")
        from test_solver_clients import FENICSX
        results = {}
        for name in ("thorax_tets.msh", "thorax_tets.xdmf"):
            p = subprocess.run([sys.executable, "-c", FENICSX, os.path.join(self.segmented_dir, name)],
                               capture_output=True, text=True, timeout=600)
            self.assertEqual(p.returncode, 0, p.stderr[-3000:])
            results[name] = got = json.loads(p.stdout.strip().splitlines()[-1])
            self.assertEqual(sorted(int(t) for t in got["volumes"]), list(range(1, 11)))
            self.assertIn(6005, got["facet_tags"])  # the LV endocardium
            self.assertLess(abs(got["energy"] - got["work"]) / got["work"], 1e-6)
        msh, xdmf = results["thorax_tets.msh"], results["thorax_tets.xdmf"]
        self.assertEqual((msh["cells"], msh["points"], msh["facet_tags"]),
                         (xdmf["cells"], xdmf["points"], xdmf["facet_tags"]))
        for tag, volume in msh["volumes"].items():
            self.assertAlmostEqual(xdmf["volumes"][tag] / volume, 1.0, places=9)
        print("FEniCSx: %d tetrahedra, %d points, %d facet tags from .msh and .xdmf" % (
            msh["cells"], msh["points"], len(msh["facet_tags"])))


class PaperTable(unittest.TestCase):
    """The paper's Table 1 case at its own 1 mm through the TetGen path, as the README gives it."""

    def test_the_papers_case_at_1mm(self):
        out = os.path.join(TMP, "paper_table_1mm")
        run_job(os.path.join(SOURCE, "Examples", "Pipelines", "paper_table.xml"), out)
        rows, whole = whole_mesh_row(os.path.join(out, "phantom_quality.csv"))
        self.assertEqual(sorted(int(r["Region"]) for r in rows if r["Region"] != "-1"), list(range(1, 11)))
        figures = run_figures(out)
        stages = figures["stage_seconds"]
        record(self, "paper_table.vertices", int(whole["np"]), "")
        record(self, "paper_table.tetrahedra", int(whole["ne"]), "")
        record(self, "paper_table.mean_q", float(whole["MeanQuality"]), "", 1.40)
        record(self, "paper_table.worst_q", float(whole["MaximumQuality"]), "", 8.0)
        record(self, "paper_table.smallest_dihedral", float(whole["MinimumDihedralAngle_deg"]), "deg", 10.0)
        record(self, "paper_table.seconds", figures["seconds"], "s")
        record(self, "paper_table.mesh_seconds", sum(v for k, v in stages.items() if k in (
            "surface", "smooth", "metric", "remesh", "tets", "quality")), "s")
        self.assertLessEqual(float(whole["MeanQuality"]), 1.40)
        self.assertLessEqual(float(whole["MaximumQuality"]), 8.0)
        self.assertGreaterEqual(float(whole["MinimumDihedralAngle_deg"]), 10.0)
        self.assertEqual(int(whole["InvertedTetrahedra"]), 0)


if __name__ == "__main__":
    unittest.main()
