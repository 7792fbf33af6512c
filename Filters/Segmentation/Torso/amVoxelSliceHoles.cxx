// The holes of a mask within its slices: what a ring of the mask encloses in one slice.
#include "amVoxelGrid.h"

amVoxelMask amVoxel::SliceHoles(const amVoxelGrid& g, const amVoxelMask& mask, int axis, std::size_t maximumVoxels)
{
  amVoxelMask holes(mask.size(), 0);
  const int nu = g.N[(axis + 1) % 3], nw = g.N[(axis + 2) % 3];
  std::vector<std::size_t> voxel, size;
  std::vector<char> outside, open;
  std::vector<int> id;
  for (int s = 0; s < g.N[axis]; ++s)
  {
    amVoxel::SliceVoxels(g, axis, s, voxel);
    outside.resize(voxel.size());
    for (std::size_t p = 0; p < voxel.size(); ++p)
      outside[p] = !mask[voxel[p]];
    // 4-connected pieces of the slice outside the mask; a piece that reaches the slice's border,
    // or is larger than the bound, is no hole.
    const int count = amVoxel::SlicePieces(outside, nu, id);
    size.assign(static_cast<std::size_t>(count), 0);
    open.assign(static_cast<std::size_t>(count), 0);
    for (std::size_t p = 0; p < voxel.size(); ++p)
      if (id[p] >= 0)
      {
        const int a = static_cast<int>(p % nu), b = static_cast<int>(p / nu);
        ++size[id[p]];
        open[id[p]] = open[id[p]] || a == 0 || b == 0 || a == nu - 1 || b == nw - 1;
      }
    for (std::size_t p = 0; p < voxel.size(); ++p)
      if (id[p] >= 0 && !open[id[p]] && size[id[p]] <= maximumVoxels)
        holes[voxel[p]] = 1;
  }
  return holes;
}
