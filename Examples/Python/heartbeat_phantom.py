#!/usr/bin/python3
"""A heartbeat on the thorax phantom and its 12-lead ECG, read as a cardiologist reads it.

Chain: the phantom's label map -> tetrahedral mesh of every organ (CGAL backend,
amLabelMapTetrahedralize) -> landmarks (amCardiacLandmarks: the heart's axis, the electrodes on the
skin) -> ventricular tags and rule-based fibres (amVentricularFibres) -> eikonal activation and
Mitchell-Schaeffer action potentials (amReactionEikonalSolver) -> the 12 leads by lead fields and
their reading (amLeadFieldECG) -> ecg.png on ECG paper, ecg.csv.

Checks: every heart node activates and repolarises, the fibres' helix turns from the endocardium to
the epicardium, the leads are finite, the QRS and QT are read, and the T wave follows the QRS in
lead II.

Usage: /usr/bin/python3 Examples/Python/heartbeat_phantom.py [OUTPUT_DIR] [SPACING_MM]
"""
import csv
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import anatomesh
from anatomesh.report import charts

out = sys.argv[1] if len(sys.argv) > 1 else "out/heartbeat_phantom"
spacing = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
os.makedirs(out, exist_ok=True)

phantom = anatomesh.amThoraxPhantomSource()
phantom.SetSpacing(spacing, spacing, spacing)
# Ventricles with a heart's walls (LV 10 mm, RV 4 mm) and an apex that points down and left-anterior.
phantom.SetHeartShape(anatomesh.amThoraxPhantomSource.VENTRICLES)
mesher = anatomesh.amLabelMapTetrahedralize()
mesher.SetInputConnection(phantom.GetOutputPort(1))
mesher.SetFacetSize(4)
mesher.SetCellSize(6)
mesher.SetFacetDistance(1)
landmarks = anatomesh.amCardiacLandmarks()
landmarks.SetInputConnection(phantom.GetOutputPort(1))

fibres = anatomesh.amVentricularFibres()
fibres.SetInputConnection(mesher.GetOutputPort(0))
fibres.SetLandmarksConnection(landmarks.GetOutputPort())
heart = anatomesh.amReactionEikonalSolver()
heart.SetInputConnection(fibres.GetOutputPort(0))
heart.SetTagsConnection(fibres.GetOutputPort(1))
ecg = anatomesh.amLeadFieldECG()
ecg.SetInputConnection(0, fibres.GetOutputPort(0))
ecg.SetHeartConnection(heart.GetOutputPort())
ecg.SetLandmarksConnection(landmarks.GetOutputPort())
ecg.Update()

print("heart: %d tetrahedra, tagged triangles LV %d, RV %d, epicardium %d, base %d"
      % (fibres.GetNumberOfHeartCells(), *(fibres.GetNumberOfTaggedTriangles(t) for t in range(1, 5))))
print("activation %.1f .. %.1f ms, last repolarisation %.1f ms (%d nodes, %.2f s)"
      % (heart.GetFirstActivation(), heart.GetLastActivation(), heart.GetLastRepolarisation(),
         heart.GetNumberOfHeartNodes(), heart.GetWallSeconds()))
print("lead fields: %d nodes, %.2f s; %d frames" % (ecg.GetNumberOfNodes(), ecg.GetLeadFieldSeconds(),
                                                     ecg.GetNumberOfFrames()))
ok = heart.GetLastActivation() > 0 and heart.GetLastRepolarisation() > heart.GetLastActivation()

# The helix angle from endocardium to epicardium (mean over the heart's cells at either side).
mesh = fibres.GetOutputDataObject(0)
f = vtk_to_numpy(mesh.GetCellData().GetArray("Fibers"))
s = vtk_to_numpy(mesh.GetCellData().GetArray("Sheets"))
depth = vtk_to_numpy(mesh.GetPointData().GetArray("TransmuralDepth"))
cells = vtk_to_numpy(mesh.GetCells().GetConnectivityArray()).reshape(-1, 4)
axis = np.array(fibres.GetUsedApexToBase())
in_heart = np.linalg.norm(f, axis=1) > 0
d = depth[cells].mean(axis=1)
longitudinal = axis - (s @ axis)[:, None] * s
longitudinal /= np.linalg.norm(longitudinal, axis=1)[:, None] + 1e-12
circumferential = np.cross(longitudinal, s)
helix = np.degrees(np.arctan2(np.sum(f * longitudinal, 1), np.sum(f * circumferential, 1)))
helix = (helix + 90) % 180 - 90
endo, epi = helix[in_heart & (d < 0.2)].mean(), helix[in_heart & (d > 0.8)].mean()
print("helix angle: %.0f degrees near the endocardium, %.0f near the epicardium" % (endo, epi))
ok = ok and endo > 30 and epi < -30

table = ecg.GetOutputDataObject(0)
names = [table.GetColumnName(c) for c in range(table.GetNumberOfColumns())]
leads = np.array([[table.GetValue(r, c).ToDouble() for c in range(len(names))] for r in range(table.GetNumberOfRows())])
ok = ok and np.all(np.isfinite(leads))
with open(os.path.join(out, "ecg.csv"), "w", newline="") as handle:
    writer = csv.writer(handle)
    writer.writerow(names)
    writer.writerows(leads.tolist())
charts.ecg_leads(leads[:, 0], {n: leads[:, k] for k, n in enumerate(names) if k > 0}, os.path.join(out, "ecg.png"))

features = ecg.GetOutputDataObject(1)
print("QRS %.0f ms, QT %.0f ms" % (ecg.GetQRSDuration(), ecg.GetQTInterval()))
polarity = {}
for r in range(features.GetNumberOfRows()):
    lead = features.GetValue(r, 0).ToString()
    polarity[lead] = features.GetValue(r, 4).ToString()
    print("  %-4s R %5.2f mV  S %6.2f mV  T %6.2f mV %s" % (lead, features.GetValue(r, 1).ToDouble(),
                                                           features.GetValue(r, 2).ToDouble(),
                                                           features.GetValue(r, 3).ToDouble(), polarity[lead]))
ok = ok and ecg.GetQRSDuration() > 40 and ecg.GetQTInterval() > ecg.GetQRSDuration() and polarity["II"] == "upright"
print("wrote ecg.png, ecg.csv in " + out)
print("OK" if ok else "FAILED")
sys.exit(0 if ok else 1)
