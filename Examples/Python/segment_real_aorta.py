#!/usr/bin/python3
"""Segment the dissected aorta of the real contrast CT in ../shared/data with polar snakes, from Python.

Nine clicks (world coordinates, mm), slice by slice with ContourModel Polar, as
Examples/Pipelines/cardiac_aorta.xml does; the Dice coefficient against the provided TotalSegmentator
mask (compared in world coordinates) is printed, and the label map written. Exits non-zero if Dice is
below MIN_DICE; exits 77 (skipped) with a message when the scan is absent.

Usage: /usr/bin/python3 Examples/Python/segment_real_aorta.py [OUTPUT_DIR] [SHARED_DATA_DIR]
"""
import os
import sys

import anatomesh

MIN_DICE = 0.85
out = sys.argv[1] if len(sys.argv) > 1 else "out/segment_real_aorta"
shared = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data")
scan = os.path.join(shared, "totalseg_cardiac_ct", "aorta_report", "ct_cropped.nii.gz")
mask_file = os.path.join(shared, "totalseg_cardiac_ct", "aorta_report", "aorta.nii.gz")
if not (os.path.exists(scan) and os.path.exists(mask_file)):
    print("skipped: the cardiac CT is absent (%s)" % scan)
    sys.exit(77)
os.makedirs(out, exist_ok=True)

ct = anatomesh.amImageReader()
ct.SetFileName(scan)

snake = anatomesh.amSnakeSegmentation()
snake.SetInputConnection(ct.GetOutputPort())
snake.SetMode(anatomesh.amSnakeSegmentation.SliceBySlice)
snake.SetContourModel(anatomesh.amSnakeSegmentation.Polar)
snake.SetMaximumAreaChange(1.5)
for x, y, z in [(1.8, -140.2, 552.2), (-2.7, -135.7, 592.7), (28.8, -116.2, 633.2), (7.8, -188.2, 675.2),
                (33.3, -99.7, 675.2), (4.8, -180.7, 715.7), (22.8, -113.2, 715.7), (19.8, -143.2, 757.7),
                (18.3, -156.7, 747.2)]:  # the last one in the arch, where the two tracks meet
    snake.AddSeed(x, y, z, 1)

clean = anatomesh.amMorphologyCleaning()
clean.SetInputConnection(snake.GetOutputPort())
clean.SetKeepLargestComponent(True)
clean.SetFillHoles(True)

writer = anatomesh.amImageWriter()
writer.SetInputConnection(clean.GetOutputPort())
writer.SetFileName(os.path.join(out, "aorta_labels.nii.gz"))
writer.Write()

mask = anatomesh.amImageReader()
mask.SetFileName(mask_file)
overlap = anatomesh.amLabelOverlap()
overlap.SetInputConnection(0, clean.GetOutputPort())
overlap.SetInputConnection(1, mask.GetOutputPort())
overlap.Update()
dice = overlap.GetDice(1)
print("aorta: Dice %.3f against the TotalSegmentator mask" % dice)
sys.exit(0 if dice >= MIN_DICE else 1)
