// The vertebral column inside a skeleton whose ribs are joined to it at their joints.
#include "amTorsoLabels.h"

#include <algorithm>
#include <cmath>

namespace
{
// The column's centre along the patient's left-right axis (world x, mm) in each slice across the
// superior axis: the median x of the deepest bone near the midline within `window` mm above and
// below (the vertebral bodies are the thickest bones there; a disc's slice borrows its
// neighbours'; the humeral heads, as thick, lie far to the sides). NaN where no such bone lies
// within the window. top[s]: the deepest such bone's depth within the window.
std::vector<double> ColumnCentres(const amVoxelGrid& g, const amVoxelMask& bone, const std::vector<float>& depth,
  const double worldX[4], int axis, const amTorso::ColumnParameters& p, std::vector<double>& top)
{
  const int slices = g.N[axis];
  std::vector<double> deepest(slices, 0.0);
  std::vector<std::vector<std::pair<float, double>>> interior(slices); // (depth, x) of each slice's bone
  const double step = std::max({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  for (std::size_t v = 0; v < bone.size(); ++v)
    if (bone[v] && depth[v] > step)
    {
      int c[3];
      g.Ijk(v, c);
      const double x = worldX[0] * c[0] + worldX[1] * c[1] + worldX[2] * c[2] + worldX[3];
      if (std::fabs(x - p.Midline) > p.MidlineReach)
        continue;
      interior[c[axis]].emplace_back(depth[v], x);
      deepest[c[axis]] = std::max<double>(deepest[c[axis]], depth[v]);
    }
  const int reach = static_cast<int>(std::ceil(p.Window / g.Spacing[axis]));
  std::vector<double> centre(slices, std::nan(""));
  top.assign(slices, 0.0);
  std::vector<double> xs;
  for (int s = 0; s < slices; ++s)
  {
    const int lo = std::max(0, s - reach), hi = std::min(slices - 1, s + reach);
    top[s] = *std::max_element(deepest.begin() + lo, deepest.begin() + hi + 1);
    if (top[s] <= 0.0)
      continue;
    xs.clear();
    for (int t = lo; t <= hi; ++t)
      for (const auto& dx : interior[t])
        if (dx.first >= 0.5 * top[s])
          xs.push_back(dx.second);
    const auto mid = xs.begin() + xs.size() / 2;
    std::nth_element(xs.begin(), mid, xs.end());
    centre[s] = *mid;
  }
  return centre;
}
}

amVoxelMask amTorso::VertebralColumn(
  const amVoxelGrid& g, const amVoxelMask& bone, const double worldX[4], int superiorAxis, const ColumnParameters& p)
{
  const std::size_t n = bone.size();
  amVoxelMask column(n, 0);
  if (superiorAxis < 0 || superiorAxis > 2)
    return bone;
  const std::vector<float> depth = amVoxel::Depth(g, bone);
  std::vector<double> top;
  const std::vector<double> centre = ColumnCentres(g, bone, depth, worldX, superiorAxis, p, top);
  // How far each bone voxel lies beyond the band (mm, along the left-right axis).
  const auto beyond = [&](std::size_t v) {
    int c[3];
    g.Ijk(v, c);
    const double x = worldX[0] * c[0] + worldX[1] * c[1] + worldX[2] * c[2] + worldX[3];
    const double m = centre[c[superiorAxis]];
    return std::isnan(m) ? 1e30 : std::fabs(x - m) - p.HalfWidth;
  };
  // The band's pieces that hold the vertebral bodies (bone at least three quarters as deep as the
  // deepest around it; the sternum, in the band too, is thinner) are the column; a rib's head and
  // neck inside the band go with it.
  amVoxelMask band(n);
  for (std::size_t v = 0; v < n; ++v)
    band[v] = bone[v] && beyond(v) <= 0.0;
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  amVoxel::Components(g, band, id, sizes);
  std::vector<char> holdsBody(sizes.size(), 0);
  const double step = std::max({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  for (std::size_t v = 0; v < n; ++v)
    if (band[v] && depth[v] > step)
    {
      int c[3];
      g.Ijk(v, c);
      holdsBody[id[v]] = holdsBody[id[v]] || depth[v] >= 0.75 * top[c[superiorAxis]];
    }
  for (std::size_t v = 0; v < n; ++v)
    column[v] = band[v] && holdsBody[id[v]];
  // Outside the band, a piece joined to the column that ends within Stub of the band is a
  // process of a vertebra (a lumbar transverse process), not a rib, which runs on round the chest.
  amVoxelMask outer(n);
  for (std::size_t v = 0; v < n; ++v)
    outer[v] = bone[v] && !column[v];
  amVoxel::Components(g, outer, id, sizes);
  std::vector<double> farthest(sizes.size(), 0.0);
  std::vector<char> joined(sizes.size(), 0);
  for (std::size_t v = 0; v < n; ++v)
    if (outer[v])
    {
      farthest[id[v]] = std::max(farthest[id[v]], beyond(v));
      g.FaceNeighbours(v, [&](std::size_t w) { joined[id[v]] = joined[id[v]] || column[w]; });
    }
  for (std::size_t v = 0; v < n; ++v)
    if (outer[v] && joined[id[v]] && farthest[id[v]] <= p.Stub)
      column[v] = 1;
  return column;
}
