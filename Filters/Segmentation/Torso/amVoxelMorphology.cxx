// Erosion by the 3x3x3 cube and opening by the 6-neighbour cross.
#include "amVoxelGrid.h"

amVoxelMask amVoxel::Erode26(const amVoxelGrid& g, const amVoxelMask& mask)
{
  amVoxelMask out(mask.size(), 0);
  for (std::size_t v = 0; v < mask.size(); ++v)
  {
    if (!mask[v])
      continue;
    bool all = true;
    g.AllNeighbours(v, [&](std::size_t w) { all = all && mask[w]; });
    out[v] = all;
  }
  return out;
}

amVoxelMask amVoxel::Open6(const amVoxelGrid& g, const amVoxelMask& mask)
{
  amVoxelMask eroded(mask.size(), 0);
  for (std::size_t v = 0; v < mask.size(); ++v)
  {
    if (!mask[v])
      continue;
    bool all = true;
    g.FaceNeighbours(v, [&](std::size_t w) { all = all && mask[w]; });
    eroded[v] = all;
  }
  amVoxelMask out = eroded;
  for (std::size_t v = 0; v < mask.size(); ++v)
    if (eroded[v])
      g.FaceNeighbours(v, [&](std::size_t w) { out[w] = 1; });
  return out;
}
