/**
 * @file    amLabelCleaning.h
 * @brief   The steps of amMorphologyCleaning on a label map of bytes (not wrapped): one label's
 *          morphology, small components and holes; the hand-over of what it gives up; the
 *          label-preserving Gaussian regularisation.
 *
 * Labels are stored x fastest (index (k * dims[1] + j) * dims[0] + i); lengths in mm.
 */
#ifndef amLabelCleaning_h
#define amLabelCleaning_h

#include "vtkType.h"

#include <functional>
#include <string>
#include <vector>

namespace amLabelCleaning
{
/// amMorphologyCleaning::Operations.
enum Operation
{
  None = 0,
  Erode = 1,
  Dilate = 2,
  Open = 3,
  Close = 4
};

struct Grid
{
  int Dims[3];
  double Spacing[3];
};

/// amMorphologyCleaning's properties of the same names.
struct Settings
{
  int Operation = None;
  double Radius = 1.0;
  double MinimumComponentVolume = 0.0; // mm^3
  bool KeepLargestComponent = false;
  bool FillHoles = false;
};

/// A component removed: its label, voxels and volume (mm^3).
struct Removed
{
  int Label;
  double Voxels;
  double Volume;
};

/// One label: the operation with a ball of Radius (per-axis voxels), then components under
/// MinimumComponentVolume (or all but the largest) removed (6-connected), then holes filled, on the
/// label's bounding box with a margin. The label grows only into unlabelled voxels (0); what it gives
/// up is handed over (HandOver). Appends the components removed. False with 'why' when ITK fails.
bool CleanLabel(const Grid& grid, const Settings& settings, int label, std::vector<unsigned char>& labels,
  std::vector<Removed>& removed, std::string& why);

/// Hands the voxels 'released' by label 'from' to their neighbours: each takes the most frequent
/// label among its 26 neighbours that are neither pending nor 'from' (the smaller of equals), front
/// after front; what no neighbour reaches becomes 0.
void HandOver(const int dims[3], std::vector<unsigned char>& labels, std::vector<vtkIdType>& released, int from);

/// Every voxel takes the label whose indicator, smoothed by a Gaussian of sigma mm, is largest
/// there (its own where equal within 1e-6). progress(fraction) after each label.
void Smooth(
  const Grid& grid, double sigma, std::vector<unsigned char>& labels, const std::function<void(double)>& progress);
}

#endif
