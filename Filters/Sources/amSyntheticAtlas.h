/**
 * @class   amSyntheticAtlas
 * @brief   A synthetic label map with many labels, for testing meshing on inputs nobody tuned for:
 *          random Voronoi cells inside an ellipsoid, optionally with thin sheets between the cells
 *          and label noise as an intensity classification leaves it.
 *
 * N seed points are drawn uniformly inside the ellipsoid that fills the grid (semi-axes 45 % of its
 * extent); every voxel centre inside takes the label 1 + the index of its nearest seed (in mm, so
 * anisotropic voxels give the same cells), outside 0. With SheetWidth > 0, the voxels whose two
 * nearest seeds are within SheetWidth mm of equidistance take the label N + 1: a membrane between
 * every pair of neighbouring cells (about one voxel thick at the voxel size). With NoiseFraction
 * p > 0, each voxel takes, with probability p, the label of one of its six face neighbours. Every
 * random number comes from a counter-based hash of (Seed, index): the same parameters give the same
 * labels whatever the thread count.
 *
 * @sa amSyntheticAtlasSource
 */
#ifndef amSyntheticAtlas_h
#define amSyntheticAtlas_h

#include "AnatomeshFiltersSourcesModule.h" // export macro

#include <array>
#include <cstdint>
#include <vector>

class ANATOMESHFILTERSSOURCES_EXPORT amSyntheticAtlas
{
public:
  int Dimensions[3] = { 96, 96, 96 };
  double Spacing[3] = { 1, 1, 1 }; // mm
  int NumberOfLabels = 50;         // Voronoi cells
  double SheetWidth = 0;           // mm; 0: no membranes
  double NoiseFraction = 0;        // of the voxels
  unsigned int Seed = 1;

  /// The labels, x fastest; 0 outside the ellipsoid. NumberOfLabels + 1 is the membrane label.
  std::vector<int32_t> Generate() const;
  /// The seed points (mm, relative to the first voxel's centre).
  std::vector<std::array<double, 3>> Seeds() const;
};

#endif
