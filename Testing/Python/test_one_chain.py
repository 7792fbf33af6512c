"""The one chain on the phantom: the simulation on the mesh segmented from the CT agrees with the
same simulation on the mesh of the phantom's exact labels (the reference run, kept only here)."""
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import anatomesh
from simulation_agreement import AgreesWithTruth

SPACING, TOLERANCE, END = 2.0, 1.0, 400.0
MAXIMUM_SIZE = 4.0  # mm: a mesh fine enough for the wave front, on both sides alike
STIMULUS = (61.0, -51.5, -25.0)  # near the apex, as in the main job
# The main job's stimulus sphere for the comparison of the two meshes: the solver's default 10 mm is
# below the critical nucleus of a free sphere (about 14 mm), and holds so few nodes of the apex's thin
# wall that when the wave leaves it depends on the elements at its border (offsets of 2.5-6.6 ms
# between the two meshes, whatever else agrees).
STIMULUS_RADIUS = 15.0


def tetrahedra(labels):
    """Label map -> surface -> remeshing -> TetGen, as the main job (Examples/Pipelines/thorax.xml) chains them."""
    surface = anatomesh.amLabelSurface()
    surface.SetInputConnection(labels)
    smooth = anatomesh.amSurfaceSmoothing()
    smooth.SetInputConnection(surface.GetOutputPort(0))
    metric = anatomesh.amCurvatureMetric()
    metric.SetInputConnection(smooth.GetOutputPort())
    metric.SetTolerance(TOLERANCE)
    metric.SetMinimumSize(SPACING)
    metric.SetAnisotropic(False)
    metric.SetMaximumSize(MAXIMUM_SIZE)
    remesh = anatomesh.amMetricRemeshing()
    remesh.SetInputConnection(metric.GetOutputPort())
    remesh.SetTolerance(TOLERANCE)
    tets = anatomesh.amTetrahedralize()
    tets.SetInputConnection(remesh.GetOutputPort())
    return tets


def simulate(tets, end=END, interval=5, endocardial=(), coupling=0, purkinje=0.0, radius=None):
    """FitzHugh-Nagumo on the mesh's region 5 and the torso potentials: the heart at the end time and the leads."""
    heart = anatomesh.amFitzHughNagumoSolver()
    heart.SetInputConnection(tets.GetOutputPort(0))
    heart.SetStimulusCenter(*STIMULUS)
    if radius is not None:
        heart.SetStimulusRadius(radius)
    heart.SetTimeStep(0.5)
    heart.SetEndTime(end)
    heart.SetOutputInterval(interval)
    for region in endocardial:
        heart.AddEndocardialRegion(region)
    heart.SetEndocardialConductionVelocity(purkinje)
    torso = anatomesh.amTorsoPotential()
    torso.SetInputConnection(0, tets.GetOutputPort(0))
    torso.SetInputConnection(1, heart.GetOutputPort())
    torso.SetCoupling(coupling)
    torso.Update()
    heart.UpdateTimeStep(end)
    h = heart.GetOutputDataObject(0).NewInstance()
    h.DeepCopy(heart.GetOutputDataObject(0))
    table = torso.GetOutputDataObject(1)
    leads = {table.GetColumn(c).GetName(): vtk_to_numpy(table.GetColumn(c)).copy()
             for c in range(table.GetNumberOfColumns())}
    return h, leads


_TRUTH = {}


def truth_tetrahedra():
    """The mesh of the phantom's exact labels (built once for every test here)."""
    if not _TRUTH:
        _TRUTH["phantom"] = anatomesh.amThoraxPhantomSource()
        _TRUTH["phantom"].SetSpacing(SPACING, SPACING, SPACING)
        _TRUTH["phantom"].SetSeed(1)
        _TRUTH["tets"] = tetrahedra(_TRUTH["phantom"].GetOutputPort(1))
    return _TRUTH["tets"]


class SegmentedAgainstTruth(AgreesWithTruth, unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.phantom = anatomesh.amThoraxPhantomSource()
        cls.phantom.SetSpacing(SPACING, SPACING, SPACING)
        cls.phantom.SetSeed(1)
        cls.snake = anatomesh.amSnakeSegmentation()
        cls.snake.SetInputConnection(cls.phantom.GetOutputPort(0))
        for x, y, z, label in [(29.4, -24.1, -28.0, 6), (-15.0, -25.0, -28.0, 7), (5.0, 40.0, 0.0, 8),
                               (5.0, -20.0, 30.0, 8)]:
            cls.snake.AddSeed(x, y, z, label)
        cls.torso = anatomesh.amTorsoSegmentation()
        cls.torso.SetInputConnection(cls.phantom.GetOutputPort(0))
        cls.torso.SetOrganConnection(cls.snake.GetOutputPort())
        cls.segmented = simulate(tetrahedra(cls.torso.GetOutputPort()), radius=STIMULUS_RADIUS)
        cls.truth = simulate(truth_tetrahedra(), radius=STIMULUS_RADIUS)


class ClinicalECG(unittest.TestCase):
    """The second coupling on the phantom's exact labels: the endocardium activated at once or spreading at a
    speed (the Purkinje network's stand-in) and the transmembrane potential as a current source give a QRS of
    60-100 ms and a few mV; the paper's apical stimulus and Dirichlet coupling give a 300 ms activation and leads of tens of mV."""

    def test_endocardial_current_source_ecg(self):
        tets = truth_tetrahedra()
        peaks, last = {}, {}
        for name, endocardial, coupling, purkinje in (("paper", (), 0, 0.0), ("clinical", (6, 7), 1, 0.0),
                                                      ("purkinje", (6, 7), 1, 1.5)):
            heart, leads = simulate(tets, end=200, interval=2, endocardial=endocardial, coupling=coupling,
                                    purkinje=purkinje)
            act = vtk_to_numpy(heart.GetPointData().GetArray("ActivationTime"))
            peaks[name] = max(np.abs(v).max() for k, v in leads.items() if k != "Time")
            last[name] = act.max()
            print("%s: activation done at %.1f ms (%.0f %% by 200 ms), largest lead %.2f mV"
                  % (name, act.max(), 100 * np.mean(act >= 0), peaks[name]))
        self.assertLess(last["clinical"], 100.0)  # ms: the whole heart within a QRS
        self.assertTrue(1.0 < peaks["clinical"] < 15.0, peaks)  # mV: a few
        # The endocardium's activation spreading from the apex at 1.5 mm/ms instead of at once: a
        # QRS of about 100 ms (60 ms at once), the leads still of a few mV.
        self.assertTrue(85.0 < last["purkinje"] < 110.0, last)
        self.assertGreater(last["purkinje"], last["clinical"] + 20.0)
        self.assertTrue(1.0 < peaks["purkinje"] < 15.0, peaks)
        self.assertGreater(peaks["paper"], 15.0)


if __name__ == "__main__":
    unittest.main()
