// The trachea and the main bronchi: the gas that leaves the field at its top as one narrow tube,
// up to where it enters the lungs.
#include "amTorsoLabels.h"

#include <algorithm>
#include <cmath>

namespace
{
// The lung closed by a ball of radius reach (mm): the dilation by the ball, then the erosion
// (the depth of the dilation beyond reach). A bronchus inside the lung, narrower than the ball,
// is filled; the lung's convex outline does not move.
amVoxelMask Closed(const amVoxelGrid& g, const amVoxelMask& lung, double reach)
{
  const std::size_t n = lung.size();
  const std::vector<float> near = amVoxel::DistanceWithin(g, lung, reach);
  amVoxelMask grown(n);
  for (std::size_t v = 0; v < n; ++v)
    grown[v] = near[v] <= reach;
  const std::vector<float> depth = amVoxel::Depth(g, grown);
  amVoxelMask closed(n);
  for (std::size_t v = 0; v < n; ++v)
    closed[v] = lung[v] || depth[v] > reach;
  return closed;
}

// Voxels of the mask in the image's top slice along the superior axis.
bool InTopSlice(const amVoxelGrid& g, std::size_t v, int superiorAxis, int superiorSign)
{
  int c[3];
  g.Ijk(v, c);
  return c[superiorAxis] == (superiorSign > 0 ? g.N[superiorAxis] - 1 : 0);
}

// The components of the mask (6-connected) of at least minimumVoxels that reach the top slice
// with a section of MinimumTracheaArea to MaximumTracheaArea (mm^2) lying, somewhere, deeper in
// the body than MinimumTracheaDepth (bodyDepth, mm).
amVoxelMask TubesFromTheTop(const amVoxelGrid& g, const amVoxelMask& mask, int superiorAxis, int superiorSign,
  std::size_t minimumVoxels, const amTorso::AirwayParameters& p, const std::vector<float>& bodyDepth)
{
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int count = amVoxel::Components(g, mask, id, sizes);
  const double pixel = g.Spacing[(superiorAxis + 1) % 3] * g.Spacing[(superiorAxis + 2) % 3];
  std::vector<std::size_t> top(count, 0);
  std::vector<float> deepest(count, 0.0f);
  for (std::size_t v = 0; v < mask.size(); ++v)
    if (id[v] >= 0 && InTopSlice(g, v, superiorAxis, superiorSign))
    {
      ++top[id[v]];
      deepest[id[v]] = std::max(deepest[id[v]], bodyDepth[v]);
    }
  amVoxelMask kept(mask.size(), 0);
  for (std::size_t v = 0; v < mask.size(); ++v)
  {
    const int c = id[v];
    kept[v] = c >= 0 && top[c] * pixel >= p.MinimumTracheaArea && top[c] * pixel <= p.MaximumTracheaArea &&
      deepest[c] >= p.MinimumTracheaDepth && sizes[c] >= minimumVoxels;
  }
  return kept;
}
}

std::size_t amTorso::Airway(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, int superiorAxis,
  int superiorSign, std::size_t minimumVoxels, const AirwayParameters& p, std::vector<std::uint8_t>& labels)
{
  std::size_t labelled = 0;
  const std::size_t n = classes.size();
  if (superiorAxis < 0 || superiorAxis > 2)
    return labelled;
  // The gas inside the body whose component leaves the field at its top as a tube: the trachea
  // (with the bronchi its lumen reaches).
  amVoxelMask gas(n), body(n);
  bool atTop = false;
  for (std::size_t v = 0; v < n; ++v)
  {
    body[v] = labels[v] != Phantom::Background;
    gas[v] = classes[v] == AirClass && body[v];
    atTop = atTop || (gas[v] && InTopSlice(g, v, superiorAxis, superiorSign));
  }
  if (!atTop)
    return labelled;
  const std::vector<float> bodyDepth = amVoxel::Depth(g, body);
  const amVoxelMask tree = TubesFromTheTop(g, gas, superiorAxis, superiorSign, minimumVoxels, p, bodyDepth);
  if (std::find(tree.begin(), tree.end(), 1) == tree.end())
    return labelled;

  // Each lung's parenchyma (its lung class, away from the tree: the lumen's partial volume, which
  // the lungs took where they were parted at the trachea, is not), closed by LungClosing: the
  // bronchi inside it are filled, its convex outline beside the trachea stays. The trachea's tree
  // enters both lungs at the carina (the oesophagus's gas, also leaving the field at its top,
  // enters none).
  const amVoxelMask besideTree = amVoxel::Dilate26(g, tree, 1);
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int count = amVoxel::Components(g, tree, id, sizes);
  std::vector<int> entersLungs(count, 0);
  amVoxelMask inLungs(n, 0);
  for (const int lung : { Phantom::RightLung, Phantom::LeftLung })
  {
    amVoxelMask parenchyma(n);
    for (std::size_t v = 0; v < n; ++v)
      parenchyma[v] = labels[v] == lung && classes[v] == LungClass && !besideTree[v];
    const amVoxelMask closed = Closed(g, parenchyma, p.LungClosing);
    std::vector<char> entered(count, 0);
    for (std::size_t v = 0; v < n; ++v)
    {
      inLungs[v] |= closed[v];
      if (id[v] >= 0 && closed[v])
        entered[id[v]] = 1;
    }
    for (int c = 0; c < count; ++c)
      entersLungs[c] += entered[c];
  }

  // The tree outside the lungs, with the partial volume of its wall (darker than LumenLevel, in
  // two rings round it), where it is still one tube from the top.
  amVoxelMask airway(n);
  for (std::size_t v = 0; v < n; ++v)
    airway[v] = tree[v] && entersLungs[id[v]] == 2 && !inLungs[v];
  for (int ring = 0; ring < 2 && p.HU; ++ring)
  {
    amVoxelMask next = airway;
    for (std::size_t v = 0; v < n; ++v)
      if (airway[v])
        g.AllNeighbours(v,
          [&](std::size_t u) { next[u] |= p.HU[u] < p.LumenLevel && labels[u] != Phantom::Background && !inLungs[u]; });
    airway.swap(next);
  }
  airway = TubesFromTheTop(g, airway, superiorAxis, superiorSign, minimumVoxels, p, bodyDepth);
  for (std::size_t v = 0; v < n; ++v)
    if (airway[v])
    {
      labels[v] = amTorso::AirwayLabel;
      ++labelled;
    }
  return labelled;
}
