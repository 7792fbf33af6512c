// The ventricles end at the heart's base: the plane through the LV's pool where it meets the
// atria or the aortic root, its normal along the LV's long axis towards the apex.
#include "amTorsoLabels.h"

#include <cmath>

namespace
{
void Position(const amVoxelGrid& g, std::size_t v, double p[3])
{
  int c[3];
  g.Ijk(v, c);
  for (int a = 0; a < 3; ++a)
    p[a] = c[a] * g.Spacing[a];
}
}

double amTorso::ValvePlane::Height(const amVoxelGrid& g, std::size_t v) const
{
  double p[3];
  Position(g, v, p);
  return (p[0] - this->Point[0]) * this->Normal[0] + (p[1] - this->Point[1]) * this->Normal[1] +
    (p[2] - this->Point[2]) * this->Normal[2];
}

amTorso::ValvePlane amTorso::FindValvePlane(const amVoxelGrid& g, const std::vector<std::uint8_t>& labels, int lv)
{
  ValvePlane plane;
  double sum[3] = { 0.0, 0.0, 0.0 };
  std::size_t count = 0;
  for (std::size_t v = 0; v < labels.size(); ++v)
  {
    if (labels[v] != lv)
      continue;
    bool base = false;
    g.FaceNeighbours(v, [&](std::size_t w) { base = base || labels[w] == Atria || labels[w] == Phantom::Aorta; });
    if (!base)
      continue;
    double p[3];
    Position(g, v, p);
    for (int a = 0; a < 3; ++a)
      sum[a] += p[a];
    ++count;
  }
  if (!count)
    return plane;
  for (int a = 0; a < 3; ++a)
    plane.Point[a] = sum[a] / count;
  // The apex: the LV's voxel farthest from its base.
  double far = 0.0;
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (labels[v] == lv)
    {
      double p[3];
      Position(g, v, p);
      const double d = std::hypot(p[0] - plane.Point[0], p[1] - plane.Point[1], p[2] - plane.Point[2]);
      if (d > far)
      {
        far = d;
        for (int a = 0; a < 3; ++a)
          plane.Normal[a] = (p[a] - plane.Point[a]) / d;
      }
    }
  plane.Found = far > 0.0;
  return plane;
}

std::size_t amTorso::EndVentriclesAtValves(
  const amVoxelGrid& g, const ValvePlane& plane, int rv, double margin, std::vector<std::uint8_t>& labels)
{
  std::size_t moved = 0;
  if (!plane.Found)
    return moved;
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (labels[v] == rv && plane.Height(g, v) < -margin)
    {
      labels[v] = Atria;
      ++moved;
    }
  return moved;
}
