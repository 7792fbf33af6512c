// Connected components, cavities and small-component removal on voxel masks and label maps.
#include "amVoxelGrid.h"

#include <algorithm>

int amVoxel::Components(
  const amVoxelGrid& g, const amVoxelMask& mask, std::vector<int>& id, std::vector<std::size_t>& sizes)
{
  const std::size_t n = g.Size();
  id.assign(n, -1);
  sizes.clear();
  std::vector<std::size_t> queue;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (!mask[v] || id[v] >= 0)
      continue;
    const int c = static_cast<int>(sizes.size());
    queue.assign(1, v);
    id[v] = c;
    for (std::size_t q = 0; q < queue.size(); ++q)
      g.FaceNeighbours(queue[q], [&](std::size_t w) {
        if (mask[w] && id[w] < 0)
        {
          id[w] = c;
          queue.push_back(w);
        }
      });
    sizes.push_back(queue.size());
  }
  return static_cast<int>(sizes.size());
}

std::size_t amVoxel::FillHoles(const amVoxelGrid& g, amVoxelMask& mask)
{
  amVoxelMask outside(mask.size(), 0);
  for (std::size_t v = 0; v < mask.size(); ++v)
    outside[v] = !mask[v];
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int n = amVoxel::Components(g, outside, id, sizes);
  std::vector<char> open(n, 0);
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < g.N[0]; ++i)
      {
        const bool border = i == 0 || j == 0 || k == 0 || i == g.N[0] - 1 || j == g.N[1] - 1 || k == g.N[2] - 1;
        if (!border)
        {
          i = g.N[0] - 2; // jump to the last voxel of the row
          continue;
        }
        const int c = id[g.Index(i, j, k)];
        if (c >= 0)
          open[c] = 1;
      }
  std::size_t filled = 0;
  for (std::size_t v = 0; v < mask.size(); ++v)
    if (id[v] >= 0 && !open[id[v]])
    {
      mask[v] = 1;
      ++filled;
    }
  return filled;
}

std::size_t amVoxel::DropSmallComponents(
  const amVoxelGrid& g, std::vector<std::uint8_t>& labels, std::size_t minimumVoxels, const std::vector<bool>& single)
{
  // One labelling of the components of every label at once (6-connected, same label): each
  // label's components keep the order of their first voxels, as a labelling of that label alone
  // numbers them, so the largest (the first of equal size) is the same.
  const std::size_t n = g.Size();
  std::vector<int> id(n, -1);
  std::vector<std::size_t> sizes;
  std::vector<std::uint8_t> labelOf;
  std::vector<std::size_t> queue;
  for (std::size_t v = 0; v < n; ++v)
  {
    const std::uint8_t l = labels[v];
    if (l == 0 || l == amVoxel::Pending || id[v] >= 0)
      continue;
    const int c = static_cast<int>(sizes.size());
    queue.assign(1, v);
    id[v] = c;
    for (std::size_t q = 0; q < queue.size(); ++q)
      g.FaceNeighbours(queue[q], [&](std::size_t w) {
        if (labels[w] == l && id[w] < 0)
        {
          id[w] = c;
          queue.push_back(w);
        }
      });
    sizes.push_back(queue.size());
    labelOf.push_back(l);
  }
  std::vector<int> largest(256, -1);
  for (int c = 0; c < static_cast<int>(sizes.size()); ++c)
  {
    int& best = largest[labelOf[c]];
    if (best < 0 || sizes[c] > sizes[best])
      best = c;
  }
  std::vector<char> drop(sizes.size(), 0);
  bool any = false;
  for (int c = 0; c < static_cast<int>(sizes.size()); ++c)
  {
    const int l = labelOf[c];
    const bool one = l < static_cast<int>(single.size()) && single[l];
    drop[c] = c != largest[l] && (sizes[c] < minimumVoxels || one);
    any = any || drop[c];
  }
  if (!any)
    return 0;
  std::vector<std::uint8_t> marked = labels;
  for (std::size_t v = 0; v < n; ++v)
    if (id[v] >= 0 && drop[id[v]])
      marked[v] = amVoxel::Pending;
  amVoxel::HandOver(g, marked);
  std::size_t changed = 0;
  for (std::size_t v = 0; v < n; ++v)
    changed += marked[v] != labels[v];
  labels.swap(marked);
  return changed;
}
