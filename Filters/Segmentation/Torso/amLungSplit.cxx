// Two lungs joined at the trachea or the bronchi, parted where they meet.
#include "amTorsoLabels.h"

#include <algorithm>
#include <numeric>

bool amTorso::SplitJoinedLungs(
  const amVoxelGrid& g, const amVoxelMask& lungs, std::size_t minimumVoxels, std::vector<std::uint8_t>& side)
{
  const std::size_t n = lungs.size();
  const std::vector<float> depth = amVoxel::Depth(g, lungs);
  const double step = std::max({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  std::size_t total = 0;
  for (const auto l : lungs)
    total += l != 0;
  // The lungs are thick where the airway joining them is thin: the deepest parts of the air fall
  // apart into two lungs at a depth between the airway's radius and the lungs'.
  for (double r = step; r <= 40.0; r += step)
  {
    amVoxelMask core(n);
    for (std::size_t v = 0; v < n; ++v)
      core[v] = lungs[v] && depth[v] > r;
    std::vector<int> id;
    std::vector<std::size_t> sizes;
    const int count = amVoxel::Components(g, core, id, sizes);
    if (count < 2)
    {
      if (count == 0)
        return false;
      continue;
    }
    std::vector<int> order(count);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sizes[a] > sizes[b]; });
    // Two cores, the second at least a tenth of the first; with the lungs thinned by r, a core
    // below the least component is noise.
    if (sizes[order[1]] * 10 < sizes[order[0]] || sizes[order[1]] < std::max<std::size_t>(1, minimumVoxels / 8))
      continue;
    if (sizes[order[0]] + sizes[order[1]] < total / 20)
      return false; // the cores left are slivers of the lungs, not the lungs
    amVoxelMask a(n), b(n);
    for (std::size_t v = 0; v < n; ++v)
    {
      a[v] = id[v] == order[0];
      b[v] = id[v] == order[1];
    }
    const std::vector<float> toA = amVoxel::Distance(g, a), toB = amVoxel::Distance(g, b);
    side.assign(n, 0);
    for (std::size_t v = 0; v < n; ++v)
      if (lungs[v])
        side[v] = toA[v] <= toB[v] ? 1 : 2;
    return true;
  }
  return false;
}
