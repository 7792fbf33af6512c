// Erosion by the 3x3x3 cube and opening by the 6-neighbour cross.
#include "amVoxelGrid.h"

#include "vtkSMPTools.h"

namespace
{
/// The voxels of the mask whose every neighbour (as 'visit' lists them) is in it. Each voxel reads
/// the mask only: on the threads.
template<typename Visit>
amVoxelMask Erode(const amVoxelMask& mask, Visit visit)
{
  amVoxelMask out(mask.size(), 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(mask.size()), [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
    {
      if (!mask[v])
        continue;
      bool all = true;
      visit(static_cast<std::size_t>(v), [&](std::size_t w) { all = all && mask[w]; });
      out[v] = all;
    }
  });
  return out;
}
}

amVoxelMask amVoxel::Erode26(const amVoxelGrid& g, const amVoxelMask& mask)
{
  return Erode(mask, [&g](std::size_t v, auto f) { g.AllNeighbours(v, f); });
}

amVoxelMask amVoxel::Open6(const amVoxelGrid& g, const amVoxelMask& mask)
{
  const amVoxelMask eroded = Erode(mask, [&g](std::size_t v, auto f) { g.FaceNeighbours(v, f); });
  // The dilation writes neighbours: in order.
  amVoxelMask out = eroded;
  for (std::size_t v = 0; v < mask.size(); ++v)
    if (eroded[v])
      g.FaceNeighbours(v, [&](std::size_t w) { out[w] = 1; });
  return out;
}

amVoxelMask amVoxel::Dilate26(const amVoxelGrid& g, const amVoxelMask& mask, int rings)
{
  // Ring by ring from the last ring's voxels only: the cost follows the mask, not the grid.
  amVoxelMask grown = mask;
  std::vector<std::size_t> front, next;
  for (std::size_t v = 0; v < mask.size(); ++v)
    if (mask[v])
      front.push_back(v);
  for (int r = 0; r < rings; ++r)
  {
    next.clear();
    for (const std::size_t v : front)
      g.AllNeighbours(v, [&](std::size_t w) {
        if (!grown[w])
        {
          grown[w] = 1;
          next.push_back(w);
        }
      });
    front.swap(next);
  }
  return grown;
}
