#!/usr/bin/python3
"""Generate the thorax phantom, print its organs' volumes against the analytic truth, write the
label map to NIfTI and read it back with its geometry.

Usage: /usr/bin/python3 Examples/Python/phantom_and_io.py [OUTPUT_DIR] [SPACING_MM]
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import anatomesh

out = sys.argv[1] if len(sys.argv) > 1 else "out/python_example"
spacing = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
os.makedirs(out, exist_ok=True)

src = anatomesh.amThoraxPhantomSource()
src.SetSpacing(spacing, spacing, spacing)
src.Update()
labels = src.GetOutputDataObject(1)
counts = np.bincount(vtk_to_numpy(labels.GetPointData().GetScalars()), minlength=src.GetNumberOfLabels())
voxel = spacing ** 3
print("%-20s %14s %14s" % ("organ", "volume mm3", "analytic mm3"))
for label in range(1, src.GetNumberOfLabels()):
    exact = src.GetExactVolume(label)
    print("%-20s %14.0f %14s" % (src.GetLabelName(label), counts[label] * voxel,
                                 "%.0f" % exact if exact > 0 else "-"))

writer = anatomesh.amImageWriter()
writer.SetInputConnection(src.GetOutputPort(1))
writer.SetFileName(os.path.join(out, "labels.nii.gz"))
assert writer.Write() == 1

reader = anatomesh.amImageReader()
reader.SetFileName(os.path.join(out, "labels.nii.gz"))
reader.Update()
back = reader.GetOutput()
assert back.GetDimensions() == labels.GetDimensions()
print("read back", back.GetDimensions(), "orientation",
      back.GetFieldData().GetAbstractArray("SourceOrientation").GetValue(0))
