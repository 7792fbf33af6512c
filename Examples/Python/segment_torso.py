#!/usr/bin/python3
"""Segment the whole simulation domain of the noisy thorax phantom: four clicks and the CT.

The torso segmentation reads the tissue classes from the scan's own histogram and prints them.
The snake segments the blood pools and the aorta from the seeds a user would click; the torso
segmentation adds the body, fat, lungs, spine, ribs and the myocardium around the blood pools, in
the phantom's label scheme. Prints each organ's Dice against the phantom's exact labels (through
amLabelOverlap) and the myocardium's intensity levels, writes the label map, and exits non-zero
if any organ scores below MIN_DICE.

Usage: /usr/bin/python3 Examples/Python/segment_torso.py [OUTPUT_DIR] [SPACING_MM]
"""
import os
import sys

import anatomesh

MIN_DICE = 0.95
out = sys.argv[1] if len(sys.argv) > 1 else "out/segment_torso"
spacing = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
os.makedirs(out, exist_ok=True)

phantom = anatomesh.amThoraxPhantomSource()
phantom.SetSpacing(spacing, spacing, spacing)
# A late contrast phase (blood 170 HU, an enhanced wall at 95) with LATE=1: the tissue classes
# and the snake's interval are read from the scan, so nothing else changes.
if os.environ.get("LATE") == "1":
    phantom.SetBloodHounsfieldUnits(170)
    phantom.SetMyocardiumHounsfieldUnits(95)

snake = anatomesh.amSnakeSegmentation()
snake.SetInputConnection(phantom.GetOutputPort(0))  # the CT, in HU
for x, y, z, label in [(29.4, -24.1, -28.0, 6), (-15.0, -25.0, -28.0, 7), (5.0, 40.0, 0.0, 8), (5.0, -20.0, 30.0, 8)]:
    snake.AddSeed(x, y, z, label)  # LV blood, RV blood, descending and ascending aorta

torso = anatomesh.amTorsoSegmentation()
torso.SetInputConnection(phantom.GetOutputPort(0))
torso.SetOrganConnection(snake.GetOutputPort())  # blood pools 6 and 7: the myocardium wraps them

overlap = anatomesh.amLabelOverlap()
overlap.SetInputConnection(torso.GetOutputPort())
overlap.SetReferenceConnection(phantom.GetOutputPort(1))
overlap.Update()

writer = anatomesh.amImageWriter()
writer.SetInputConnection(torso.GetOutputPort())
writer.SetFileName(os.path.join(out, "torso_labels.nii.gz"))
if writer.Write() != 1:
    sys.exit("writing the label map failed")

worst = 1.0
for label in range(1, 11):
    dice = overlap.GetDice(label)
    print("%-22s Dice %.4f" % (phantom.GetLabelName(label), dice))
    worst = min(worst, dice)
classes = torso.GetOutput().GetFieldData().GetArray("TissueClasses")  # read from this scan
for c, name in enumerate(["air", "lung", "fat", "soft tissue", "contrast blood", "bone"]):
    mean, sigma, weight, found, upper = (classes.GetComponent(c, k) for k in range(1, 6))
    print("class %-15s %s" % (name, "centre %7.1f HU, spread %5.1f HU, %4.1f %% of the body, up to %s"
                              % (mean, sigma, 100 * weight, "%.0f HU" % upper if upper < 1e29 else "the top")
                              if found else "not in this scan"))
# The heart's landmarks and the 12-lead electrodes, computed on the segmented body.
landmarks = anatomesh.amCardiacLandmarks()
landmarks.SetInputConnection(torso.GetOutputPort())
landmarks.Update()
names = landmarks.GetOutput().GetPointData().GetAbstractArray("Name")
for i in range(landmarks.GetOutput().GetNumberOfPoints()):
    if names.GetValue(i) in ("V1", "V4", "V6", "Stimulus"):
        print("%-9s at (%.0f, %.0f, %.0f) mm" % ((names.GetValue(i),) + landmarks.GetOutput().GetPoint(i)))
levels = torso.GetOutput().GetFieldData().GetArray("MyocardiumLevels")
print("myocardium: wall %.1f HU, surroundings %.1f HU, threshold %.1f HU, noise of the average %.2f HU"
      % tuple(levels.GetValue(i) for i in range(4)))
sys.exit(0 if worst >= MIN_DICE else 1)
