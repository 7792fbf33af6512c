// The myocardium: the wall around the blood pools, told from the tissue around it by its mean
// intensity where single voxels cannot tell it (50 against 40 HU under 20 HU of noise).
#include "amTorsoLabels.h"

#include <algorithm>
#include <cmath>

namespace
{
// A box of the grid: the work happens around the pools only.
struct Box
{
  int Lo[3], Hi[3]; // inclusive
  amVoxelGrid Grid;
  std::size_t Global(const amVoxelGrid& g, std::size_t local) const
  {
    int c[3];
    this->Grid.Ijk(local, c);
    return g.Index(c[0] + this->Lo[0], c[1] + this->Lo[1], c[2] + this->Lo[2]);
  }
};

double Median(std::vector<float> values)
{
  if (values.empty())
    return 0.0;
  const auto mid = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

// A ventricle's blood lies inside its wall: where the scan shows the pool against fat or lung (a
// wall of 3-4 mm lost in partial volume, as the RV's free wall often is), the fat or lung next to it
// is the wall.
bool EnclosesPool(std::uint8_t label)
{
  using P = amTorso::Phantom;
  return label == P::Fat || label == P::RightLung || label == P::LeftLung;
}

// The voxels the wall grows over (the pools and the soft tissue the wall may hold): within the
// least wall of the pools; where the intensity tells the wall, within MaximumThickness on the
// wall's side of the threshold; else within the LV's (and any other pool's) Thickness or the RV's
// RightThickness (its free wall is a third as thick; the septum is the LV's).
amVoxelMask GrowRegion(const amVoxelGrid& g, const Box& box, const amTorso::WallParameters& p,
  const amTorso::WallReport& report, double contrast, const amVoxelMask& pools, const amVoxelMask& candidate,
  const std::vector<float>& d, const std::vector<float>& level, const std::vector<std::uint8_t>& labels)
{
  const amVoxelGrid& b = box.Grid;
  const std::size_t n = b.Size();
  std::vector<float> dLeft, dRight;
  if (!report.Contrast && p.PoolLabels.size() > 1)
  {
    amVoxelMask right(n, 0), left(n, 0);
    for (std::size_t v = 0; v < n; ++v)
      if (pools[v])
        (labels[box.Global(g, v)] == p.PoolLabels[1] ? right : left)[v] = 1;
    dLeft = amVoxel::DistanceWithin(b, left, p.Thickness);
    dRight = amVoxel::DistanceWithin(b, right, p.RightThickness);
  }
  amVoxelMask grow(n, 0);
  for (std::size_t v = 0; v < n; ++v)
  {
    const double height = p.Base.Found ? p.Base.Height(g, box.Global(g, v)) : 0.0;
    if (pools[v])
      grow[v] = 1;
    else if (height < -p.BaseMargin)
      continue; // above the base: the atria's and the great vessels' walls are not the ventricles'
    else if (p.Base.Found && d[v] <= p.RightThickness && EnclosesPool(labels[box.Global(g, v)]))
      grow[v] = 1;
    else if (candidate[v])
    {
      // A ventricle's blood lies inside its wall: the soft tissue next to the pools is wall even
      // where a thin wall's average reads as its surroundings.
      if (d[v] <= p.MinimumThickness)
        grow[v] = 1;
      else if (report.Contrast)
        grow[v] =
          d[v] <= p.MaximumThickness && (contrast > 0 ? level[v] >= report.Threshold : level[v] <= report.Threshold);
      else if (!dLeft.empty())
        grow[v] = dLeft[v] <= p.Thickness || dRight[v] <= p.RightThickness;
      else
        grow[v] = d[v] <= p.Thickness;
    }
  }
  return grow;
}

// The wall's outline where intensity told it: the average that told it resolves no feature finer
// than its own width, so the threshold's contour has bumps and dents of that size that are the
// average's noise, not the wall's shape. The heart (pools and wall) averaged over a Gaussian of
// that width and cut at one half keeps the outline where it is flat (a convex outline moves in by
// about sigma squared over its radius) and removes them; the soft tissue next to the pools stays
// wall, and no wall grows above the base or beyond MaximumThickness.
void SmoothOutline(const amVoxelGrid& b, const Box& box, const amVoxelGrid& g, const amTorso::WallParameters& p,
  const amVoxelMask& candidate, const amVoxelMask& pools, const std::vector<float>& d, double sigma, amVoxelMask& heart)
{
  const std::size_t n = b.Size();
  std::vector<float> f(n);
  for (std::size_t v = 0; v < n; ++v)
    f[v] = heart[v] ? 1.0f : 0.0f;
  amVoxel::Gaussian(b, f, sigma);
  for (std::size_t v = 0; v < n; ++v)
  {
    if (pools[v] || (heart[v] && d[v] <= p.MinimumThickness))
      continue;
    const bool belowBase = !p.Base.Found || p.Base.Height(g, box.Global(g, v)) >= -p.BaseMargin;
    heart[v] = f[v] >= 0.5f && candidate[v] && d[v] <= p.MaximumThickness && belowBase;
  }
}
}

amTorso::WallReport amTorso::MyocardiumWall(const amVoxelGrid& g, const float* hu,
  const std::vector<std::uint8_t>& classes, const WallParameters& p, std::vector<std::uint8_t>& labels)
{
  WallReport report;
  std::vector<bool> pool(256, false);
  for (const int l : p.PoolLabels)
    if (l > 0 && l < 255)
      pool[l] = true;
  Box box;
  for (int a = 0; a < 3; ++a)
  {
    box.Lo[a] = g.N[a];
    box.Hi[a] = -1;
  }
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (pool[labels[v]])
    {
      int c[3];
      g.Ijk(v, c);
      for (int a = 0; a < 3; ++a)
      {
        box.Lo[a] = std::min(box.Lo[a], c[a]);
        box.Hi[a] = std::max(box.Hi[a], c[a]);
        report.PoolsAtBorder = report.PoolsAtBorder || c[a] == 0 || c[a] == g.N[a] - 1;
      }
      ++report.PoolVoxels;
    }
  if (!report.PoolVoxels)
    return report;
  // At least 1.5 voxels: fewer voxels under the Gaussian leave too much noise in the average.
  const double hmax = std::max({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  const double sigma = std::max(p.Sigma, 1.5 * hmax);
  const double reach = p.MaximumThickness + 10.0 + 3.0 * sigma;
  for (int a = 0; a < 3; ++a)
  {
    const int r = static_cast<int>(std::ceil(reach / g.Spacing[a]));
    box.Lo[a] = std::max(0, box.Lo[a] - r);
    box.Hi[a] = std::min(g.N[a] - 1, box.Hi[a] + r);
    box.Grid.N[a] = box.Hi[a] - box.Lo[a] + 1;
    box.Grid.Spacing[a] = g.Spacing[a];
  }
  const amVoxelGrid& b = box.Grid;
  const std::size_t n = b.Size();
  amVoxelMask pools(n), candidate(n), soft(n);
  std::vector<float> value(n), blood;
  for (std::size_t v = 0; v < n; ++v)
  {
    const std::size_t w = box.Global(g, v);
    pools[v] = pool[labels[w]];
    candidate[v] = labels[w] == Phantom::SoftTissue || labels[w] == amVoxel::Pending;
    value[v] = hu[w];
    if (pools[v])
      blood.push_back(value[v]);
  }
  report.PoolLevel = Median(blood);
  const std::vector<float> d = amVoxel::Distance(b, pools);
  const double shellIn = std::max(3.0, 1.5 * hmax), shellOut = std::max(6.0, 3.0 * hmax);
  // The wall is soft tissue darker than half-way from its raw level to the pools': brighter voxels
  // are the pools' partial volume (a soft kernel spreads it over millimetres), whatever the phase.
  std::vector<float> raw;
  for (std::size_t v = 0; v < n; ++v)
    if (candidate[v] && classes[box.Global(g, v)] == SoftClass && d[v] >= shellIn && d[v] <= shellOut)
      raw.push_back(value[v]);
  const double rawWall = Median(raw);
  const double bright = report.PoolLevel > rawWall + p.MinimumContrast ? 0.5 * (report.PoolLevel + rawWall) : 1e30;
  for (std::size_t v = 0; v < n; ++v)
    soft[v] = classes[box.Global(g, v)] == SoftClass && value[v] < bright;
  // The mean over soft tissue only, away from its edges: partial volume with lung or blood would
  // pull the wall's level towards theirs.
  const amVoxelMask inner = amVoxel::Erode26(b, soft);
  std::vector<float> level(n);
  double contrast = 0.0;
  // The average's Gaussian grows (by half, up to two and a half times) while the wall's contrast
  // stands less than four times above the average's noise: a noisy scan needs a wider average for
  // a wall whose contrast it shows.
  for (double width = sigma; width <= 2.5 * sigma + 1e-9; width *= 1.5)
  {
    std::vector<float> weight(n);
    for (std::size_t v = 0; v < n; ++v)
    {
      weight[v] = inner[v] ? 1.0f : 0.0f;
      level[v] = inner[v] ? value[v] : 0.0f;
    }
    amVoxel::Gaussian(b, weight, width);
    amVoxel::Gaussian(b, level, width);
    for (std::size_t v = 0; v < n; ++v)
      level[v] = weight[v] > 1e-3f ? level[v] / weight[v] : value[v];

    std::vector<float> wall, around;
    for (std::size_t v = 0; v < n; ++v)
    {
      if (!candidate[v] || !inner[v])
        continue;
      if (d[v] >= shellIn && d[v] <= shellOut)
        wall.push_back(level[v]);
      else if (d[v] > p.MaximumThickness && d[v] <= p.MaximumThickness + 10.0)
        around.push_back(level[v]);
    }
    report.WallLevel = Median(wall);
    report.SurroundingLevel = around.empty() ? report.WallLevel : Median(around);
    std::vector<float> spread(wall.size());
    for (std::size_t i = 0; i < wall.size(); ++i)
      spread[i] = static_cast<float>(std::fabs(wall[i] - report.WallLevel));
    report.Noise = 1.4826 * Median(spread);
    report.Sigma = width;
    contrast = report.WallLevel - report.SurroundingLevel;
    report.Contrast =
      !wall.empty() && !around.empty() && std::fabs(contrast) >= std::max(p.MinimumContrast, 2.0 * report.Noise);
    if (std::fabs(contrast) < p.MinimumContrast || std::fabs(contrast) >= 4.0 * report.Noise)
      break;
  }
  report.Threshold = 0.5 * (report.WallLevel + report.SurroundingLevel);

  const amVoxelMask grow = GrowRegion(g, box, p, report, contrast, pools, candidate, d, level, labels);
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int count = amVoxel::Components(b, grow, id, sizes);
  std::vector<char> keep(count, 0);
  for (std::size_t v = 0; v < n; ++v)
    if (pools[v])
      keep[id[v]] = 1;
  amVoxelMask heart(n, 0);
  for (std::size_t v = 0; v < n; ++v)
    heart[v] = id[v] >= 0 && keep[id[v]];
  if (report.Contrast)
    SmoothOutline(b, box, g, p, candidate, pools, d, report.Sigma, heart);
  // Cavities the noise leaves inside the wall belong to it.
  amVoxelMask filled = heart;
  amVoxel::FillHoles(b, filled);
  for (std::size_t v = 0; v < n; ++v)
    if ((heart[v] || (filled[v] && candidate[v])) && !pools[v])
    {
      labels[box.Global(g, v)] = Phantom::Myocardium;
      ++report.Voxels;
    }
  return report;
}
