// Air below the lungs, across the diaphragm: the stomach's and the bowel's gas, and the
// abdominal fat that a window starting above fat shows as air.
#include "amTorsoLabels.h"

#include <algorithm>

amVoxelMask amTorso::GasBelowLungs(const amVoxelGrid& g, const amVoxelMask& air, int superiorAxis, int superiorSign)
{
  const std::size_t n = air.size();
  amVoxelMask below(n, 0);
  if (superiorAxis < 0 || superiorAxis > 2)
    return below;
  const std::vector<float> depth = amVoxel::Depth(g, air);
  // A part of the air joined to the rest by a neck two voxels thinner than its own deepest point
  // is a basin of its own (the lungs are thick, the passages between them and the gas below the
  // diaphragm thin).
  const double step = std::max({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  std::vector<int> basinOfVoxel;
  const int count = amVoxel::Basins(g, air, depth, 2.0 * step, basinOfVoxel);
  std::vector<std::size_t> size(count, 0), covered(count, 0);
  for (std::size_t v = 0; v < n; ++v)
    if (basinOfVoxel[v] >= 0)
      ++size[basinOfVoxel[v]];
  // Walk every column from the head down: a voxel is covered when air of another, larger basin
  // lies above it across tissue (the diaphragm, or the organs under it).
  const int a = superiorAxis, b = (a + 1) % 3, c = (a + 2) % 3;
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(g.N[0]), static_cast<std::size_t>(g.N[0]) * g.N[1] };
  for (int jc = 0; jc < g.N[c]; ++jc)
    for (int jb = 0; jb < g.N[b]; ++jb)
    {
      int above = -1;          // the basin of the nearest air above
      int previous = -1;       // the basin of the voxel just above (-1: tissue)
      bool runCovered = false; // the run of air this voxel is in lies under another basin
      for (int t = 0; t < g.N[a]; ++t)
      {
        const int ia = superiorSign > 0 ? g.N[a] - 1 - t : t;
        const std::size_t v = ia * stride[a] + jb * stride[b] + jc * stride[c];
        const int here = basinOfVoxel[v];
        if (here >= 0 && here != previous)
          runCovered = previous < 0 && above >= 0 && above != here && size[above] > size[here];
        if (here >= 0)
        {
          covered[here] += runCovered;
          above = here;
        }
        previous = here;
      }
    }
  // A basin more than half under a larger one is below the lungs (the lungs are never under
  // other air).
  for (std::size_t v = 0; v < n; ++v)
    below[v] = basinOfVoxel[v] >= 0 && 2 * covered[basinOfVoxel[v]] > size[basinOfVoxel[v]];
  return below;
}
