#!/usr/bin/python3
"""The paper's case study on the thorax phantom: a depolarisation cycle on the heart and the
potentials it makes on the body surface, with a virtual 12-lead ECG.

Chain: the phantom's label map -> tetrahedral mesh of every organ (CGAL backend,
amLabelMapTetrahedralize) -> FitzHugh-Nagumo (Rogers-McCulloch) monodomain on the myocardium
(amFitzHughNagumoSolver, stimulus near the apex) -> quasi-static Poisson problem on the torso
(amTorsoPotential) -> activation map (PNG), body-surface potential (PNG) and the 12 leads (PNG, CSV).

Checks: the whole heart depolarises; activation times are monotone away from the stimulus (every
node outside the stimulus has a neighbour activated earlier); body-surface potentials and leads are
produced and finite.

Usage: /usr/bin/python3 Examples/Python/simulation_phantom.py [OUTPUT_DIR] [SPACING_MM] [END_TIME_MS]
"""
import csv
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from vtkmodules.util.numpy_support import vtk_to_numpy

import anatomesh

# Large arrays reused from filter to filter, as the anatomesh command has them (glibc only).
anatomesh.keep_freed_memory()

out = sys.argv[1] if len(sys.argv) > 1 else "out/simulation_phantom"
spacing = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
end_time = float(sys.argv[3]) if len(sys.argv) > 3 else 500.0
os.makedirs(out, exist_ok=True)

phantom = anatomesh.amThoraxPhantomSource()
phantom.SetSpacing(spacing, spacing, spacing)
mesher = anatomesh.amLabelMapTetrahedralize()
mesher.SetInputConnection(phantom.GetOutputPort(1))  # the exact labels: myocardium and torso
mesher.SetFacetSize(4)
mesher.SetCellSize(6)
mesher.SetFacetDistance(1)

stimulus = (61.0, -51.5, -25.0)  # inside the myocardium near the apex
heart = anatomesh.amFitzHughNagumoSolver()
heart.SetInputConnection(mesher.GetOutputPort(0))
heart.SetStimulusCenter(*stimulus)
heart.SetTimeStep(0.5)
heart.SetEndTime(end_time)
heart.SetOutputInterval(5)

torso = anatomesh.amTorsoPotential()
torso.SetInputConnection(0, mesher.GetOutputPort(0))
torso.SetInputConnection(1, heart.GetOutputPort())
torso.Update()

mesh = mesher.GetOutputDataObject(0)
print("mesh: %d points, %d tetrahedra" % (mesh.GetNumberOfPoints(), mesh.GetNumberOfCells()))
print("heart: %d nodes, %d steps of %.2f ms, %.1f CG iterations per step, %.2f s"
      % (heart.GetNumberOfHeartNodes(), heart.GetNumberOfSteps(), heart.GetTimeStep(), heart.GetMeanIterations(),
         heart.GetWallSeconds()))
print("torso: %d nodes (%d on the heart), %d times solved, Cholesky factor %.1f M non-zeros in %.2f s, solves %.2f s"
      % (torso.GetNumberOfTorsoNodes(), torso.GetNumberOfHeartNodes(), torso.GetNumberOfSolves(),
         torso.GetFactorNonZeros() / 1e6, torso.GetFactorSeconds(), torso.GetWallSeconds()))

# The heart at the last time: every node activated, activation monotone away from the stimulus.
heart.UpdateTimeStep(end_time)
h = heart.GetOutput()
points = vtk_to_numpy(h.GetPoints().GetData())
act = vtk_to_numpy(h.GetPointData().GetArray("ActivationTime"))
cells = vtk_to_numpy(h.GetCells().GetConnectivityArray()).reshape(-1, 4)
ok = True
activated = np.mean(act >= 0)
print("activated: %.2f %% of the heart; activation times %.1f .. %.1f ms" % (100 * activated, act.min(), act.max()))
ok = ok and activated == 1.0
earliest_neighbour = np.full(len(act), np.inf)
for a in range(4):
    for b in range(4):
        if a != b:
            np.minimum.at(earliest_neighbour, cells[:, a], act[cells[:, b]])
in_stimulus = np.linalg.norm(points - np.array(stimulus), axis=1) <= heart.GetStimulusRadius()
local_minima = np.sum((earliest_neighbour >= act) & ~in_stimulus)
print("nodes outside the stimulus with no earlier neighbour (should be 0): %d" % local_minima)
ok = ok and local_minima == 0

# Activation map: the heart's nodes seen from the front (-y), coloured by activation time.
fig, ax = plt.subplots(figsize=(6, 5))
order = np.argsort(-points[:, 1])  # draw back to front
sc = ax.scatter(points[order, 0], points[order, 2], c=act[order], s=6, cmap="jet")
ax.plot(stimulus[0], stimulus[2], "k*", markersize=14, label="stimulus")
ax.set_xlabel("x (mm, patient's left)")
ax.set_ylabel("z (mm, up)")
ax.set_aspect("equal")
ax.set_title("Activation time, anterior view")
ax.legend(loc="lower left")
fig.colorbar(sc, label="ms")
fig.savefig(os.path.join(out, "activation_map.png"), dpi=110, bbox_inches="tight")
plt.close(fig)

# Body-surface potential at the time of the largest lead II.
table = torso.GetOutputDataObject(1)
names = [table.GetColumnName(c) for c in range(table.GetNumberOfColumns())]
leads = np.array([[table.GetValue(r, c).ToDouble() for c in range(len(names))] for r in range(table.GetNumberOfRows())])
frames = int(round(end_time / 5.0)) + 1
print("leads table: %d times x %d columns" % leads.shape)
ok = ok and np.all(np.isfinite(leads)) and leads.shape == (frames, 13)
peak = leads[np.argmax(np.abs(leads[:, names.index("II")])), 0]
torso.UpdateTimeStep(peak)
body = torso.GetOutputDataObject(0)
phi = vtk_to_numpy(body.GetPointData().GetArray("Potential"))
bp = vtk_to_numpy(body.GetPoints().GetData())
front = bp[:, 1] < -40  # the anterior chest
fig, ax = plt.subplots(figsize=(6, 5))
limit = np.max(np.abs(phi[front])) or 1.0
sc = ax.scatter(bp[front, 0], bp[front, 2], c=phi[front], s=4, cmap="RdBu_r", vmin=-limit, vmax=limit)
ax.set_aspect("equal")
ax.set_title("Potential on the anterior torso at %.0f ms" % peak)
ax.set_xlabel("x (mm)")
ax.set_ylabel("z (mm)")
fig.colorbar(sc, label="mV")
fig.savefig(os.path.join(out, "body_surface_potential.png"), dpi=110, bbox_inches="tight")
plt.close(fig)
print("body-surface potential at %.0f ms: %.2f .. %.2f mV" % (peak, phi.min(), phi.max()))
ok = ok and np.all(np.isfinite(phi)) and np.ptp(phi[front]) > 0

# The 12 leads.
fig, axes = plt.subplots(4, 3, figsize=(10, 8), sharex=True)
for k, name in enumerate(names[1:]):
    ax = axes[k % 4][k // 4]
    ax.plot(leads[:, 0], leads[:, k + 1], "k-", linewidth=1)
    ax.set_title(name, fontsize=9)
    ax.grid(True, alpha=0.3)
for ax in axes[-1]:
    ax.set_xlabel("ms")
fig.suptitle("Virtual 12-lead ECG (mV)")
fig.tight_layout()
fig.savefig(os.path.join(out, "ecg_leads.png"), dpi=110)
plt.close(fig)
with open(os.path.join(out, "ecg_leads.csv"), "w", newline="") as f:
    writer = csv.writer(f)
    writer.writerow(names)
    writer.writerows(leads.tolist())
print("leads: %s; largest |lead| %.2f mV" % (", ".join(names[1:]), np.max(np.abs(leads[:, 1:]))))
ok = ok and np.max(np.abs(leads[:, 1:])) > 0.1
print("wrote activation_map.png, body_surface_potential.png, ecg_leads.png, ecg_leads.csv in " + out)
print("OK" if ok else "FAILED")
sys.exit(0 if ok else 1)
