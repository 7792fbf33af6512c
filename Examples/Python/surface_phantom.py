#!/usr/bin/python3
"""From the thorax phantom's label map to one smoothed, conforming multi-material surface.

Extracts the surface of every organ at once (amLabelSurface), prints the per-region topology
table (every region must be closed, oriented and manifold), smooths it (amSurfaceSmoothing) and
measures how far smoothing moved it (amSurfaceDistance). Writes the surfaces as VTK XML (.vtp)
and Medit (.mesh). Exits non-zero if a region is not a closed oriented manifold or if smoothing
moved the surface more than the voxel diagonal.

Usage: /usr/bin/python3 Examples/Python/surface_phantom.py [OUTPUT_DIR] [SPACING_MM]
"""
import math
import os
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

import anatomesh

out = sys.argv[1] if len(sys.argv) > 1 else "out/surface_phantom"
spacing = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
os.makedirs(out, exist_ok=True)

phantom = anatomesh.amThoraxPhantomSource()
phantom.SetSpacing(spacing, spacing, spacing)

surface = anatomesh.amLabelSurface()
surface.SetInputConnection(phantom.GetOutputPort(1))  # the exact labels
surface.Update()
table = surface.GetOutputDataObject(1)

ok = True
print("%5s %9s %9s %6s %5s %8s %12s %12s" % ("label", "triangles", "vertices", "Euler", "parts",
                                            "bad", "volume mm3", "voxels mm3"))
for r in range(table.GetNumberOfRows()):
    row = {table.GetColumnName(c): table.GetValue(r, c).ToDouble() for c in range(table.GetNumberOfColumns())}
    bad = row["BoundaryEdges"] + row["NonManifoldEdges"] + row["MisorientedEdges"] + row["NonManifoldVertices"]
    ok = ok and bad == 0
    print("%5d %9d %9d %6d %5d %8d %12.0f %12.0f" % (row["Label"], row["Triangles"], row["Vertices"],
          row["EulerCharacteristic"], row["Components"], bad, row["Volume"], row["VoxelVolume"]))

smooth = anatomesh.amSurfaceSmoothing()
smooth.SetInputConnection(surface.GetOutputPort(0))

distance = anatomesh.amSurfaceDistance()
distance.SetInputConnection(0, smooth.GetOutputPort())
distance.SetInputConnection(1, surface.GetOutputPort(0))
distance.Update()
print("smoothing moved the surface by at most %.3f mm (mean %.3f mm); bound %.3f mm"
      % (distance.GetHausdorff(), distance.GetMeanAToB(), smooth.GetUsedMaximumDisplacement()))
ok = ok and distance.GetHausdorff() <= math.sqrt(3) / 2 * spacing + 1e-6

for name, port in (("surface_voxels", surface.GetOutputPort(0)), ("surface_smooth", smooth.GetOutputPort())):
    w = vtkXMLPolyDataWriter()
    w.SetInputConnection(port)
    w.SetFileName(os.path.join(out, name + ".vtp"))
    w.SetDataModeToBinary()  # appended data is unreadable with Debian 12's expat (see README)
    w.Write()
medit = anatomesh.amMeditWriter()
medit.SetInputConnection(smooth.GetOutputPort())
medit.SetRegionArrayName("Labels")
medit.SetFileName(os.path.join(out, "surface_smooth.mesh"))
medit.Write()
print("wrote", out)
sys.exit(0 if ok else 1)
