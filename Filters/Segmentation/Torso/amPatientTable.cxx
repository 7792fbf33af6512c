// The patient table (couch) the body lies on: made along the scanner's axis, so the same in every
// slice, where the body's outline changes from slice to slice.
#include "amTorsoLabels.h"

#include <algorithm>
#include <cmath>

namespace
{
// The plane across the axis as a grid of one slice: pixel p of it is the column of voxels
// SliceVoxels(g, axis, s, voxel)[p] over every slice s.
amVoxelGrid PlaneAcross(const amVoxelGrid& g, int axis)
{
  amVoxelGrid plane;
  plane.N[0] = g.N[(axis + 1) % 3];
  plane.N[1] = g.N[(axis + 2) % 3];
  plane.N[2] = 1;
  plane.Spacing[0] = g.Spacing[(axis + 1) % 3];
  plane.Spacing[1] = g.Spacing[(axis + 2) % 3];
  plane.Spacing[2] = 1.0;
  return plane;
}

// How many slices hold each column's pixel in the mask, or with near set a neighbour within one
// pixel across: a table that sags or is tilted by a pixel over the scan's length is still counted
// in every slice.
std::vector<int> SlicesHolding(const amVoxelGrid& g, int axis, const amVoxelMask& mask, bool near)
{
  const amVoxelGrid plane = PlaneAcross(g, axis);
  std::vector<int> count(plane.Size(), 0);
  std::vector<std::size_t> voxel;
  amVoxelMask in(plane.Size());
  for (int s = 0; s < g.N[axis]; ++s)
  {
    amVoxel::SliceVoxels(g, axis, s, voxel);
    for (std::size_t p = 0; p < voxel.size(); ++p)
      in[p] = mask[voxel[p]];
    const amVoxelMask held = near ? amVoxel::Dilate26(plane, in, 1) : in;
    for (std::size_t p = 0; p < held.size(); ++p)
      count[p] += held[p] != 0;
  }
  return count;
}
}

amVoxelMask amTorso::PatientTable(
  const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, int axis, const TableParameters& p)
{
  const std::size_t n = classes.size();
  amVoxelMask table(n, 0);
  if (axis < 0 || axis > 2 || g.N[axis] < p.MinimumSlices || g.N[axis] * g.Spacing[axis] < p.MinimumLength)
    return table; // too few slices to tell a table from a body that does not change
  const amVoxelGrid plane = PlaneAcross(g, axis);
  const std::size_t m = plane.Size();
  // The table's shells are at least as dense as fat; its foam core reads as lung, its air gaps as
  // air.
  amVoxelMask dense(n), air(n), foam(n);
  for (std::size_t v = 0; v < n; ++v)
  {
    air[v] = classes[v] == AirClass;
    foam[v] = classes[v] == LungClass;
    dense[v] = !air[v] && !foam[v];
  }
  const int slices = g.N[axis];
  const int least = static_cast<int>(std::ceil(p.Constancy * slices));
  const std::vector<int> denseCount = SlicesHolding(g, axis, dense, true),
                         foamCount = SlicesHolding(g, axis, foam, true), airCount = SlicesHolding(g, axis, air, false);
  amVoxelMask always(m), alwaysAir(m);
  for (std::size_t q = 0; q < m; ++q)
  {
    always[q] = denseCount[q] >= least;
    alwaysAir[q] = airCount[q] >= least;
  }
  // The parts of the constant footprint thinner than the table (counted a pixel wider on each side,
  // as SlicesHolding counts it): the body's constant part (the spine, the back of a scan that
  // covers little of the body) is thick.
  const double h = std::max(plane.Spacing[0], plane.Spacing[1]);
  const double half = p.MaximumThickness / 2.0 + h;
  const std::vector<float> depth = amVoxel::Depth(plane, always);
  amVoxelMask core(m);
  for (std::size_t q = 0; q < m; ++q)
    core[q] = depth[q] > half;
  const std::vector<float> toCore = amVoxel::DistanceWithin(plane, core, half + h);
  amVoxelMask thin(m);
  for (std::size_t q = 0; q < m; ++q)
    thin[q] = always[q] && toCore[q] > half + h;
  // A table is long across the body and has the outside air beside it in every slice.
  const amVoxelMask grown = amVoxel::Dilate26(plane, thin, 1);
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int count = amVoxel::Components(plane, grown, id, sizes);
  std::vector<int> lo[2], hi[2];
  for (auto* bound : { &lo[0], &lo[1] })
    bound->assign(count, 1 << 30);
  for (auto* bound : { &hi[0], &hi[1] })
    bound->assign(count, -1);
  std::vector<char> besideAir(count, 0), cut(count, 0);
  for (std::size_t q = 0; q < m; ++q)
  {
    if (id[q] < 0 || !thin[q])
      continue;
    int c[3];
    plane.Ijk(q, c);
    for (int a = 0; a < 2; ++a)
    {
      lo[a][id[q]] = std::min(lo[a][id[q]], c[a]);
      hi[a][id[q]] = std::max(hi[a][id[q]], c[a]);
      cut[id[q]] = cut[id[q]] || c[a] == 0 || c[a] == plane.N[a] - 1;
    }
    plane.AllNeighbours(q, [&](std::size_t r) { besideAir[id[q]] = besideAir[id[q]] || alwaysAir[r]; });
  }
  amVoxelMask footprint(m, 0);
  for (std::size_t q = 0; q < m; ++q)
  {
    const int c = id[q];
    if (c < 0 || !besideAir[c] || hi[0][c] < 0)
      continue;
    const double extent =
      std::hypot((hi[0][c] - lo[0][c]) * plane.Spacing[0], (hi[1][c] - lo[1][c]) * plane.Spacing[1]);
    // A table the field of view cuts shows a part of its width.
    footprint[q] = extent >= (cut[c] ? 0.5 : 1.0) * p.MinimumExtent;
  }
  // The foam between the shells: constant columns of lung-like density that touch the shells.
  amVoxelMask foamColumns(m);
  for (std::size_t q = 0; q < m; ++q)
    foamColumns[q] = foamCount[q] >= least && !footprint[q];
  const int foamPieces = amVoxel::Components(plane, foamColumns, id, sizes);
  std::vector<char> touches(foamPieces, 0);
  for (std::size_t q = 0; q < m; ++q)
    if (id[q] >= 0)
      plane.AllNeighbours(q, [&](std::size_t r) { touches[id[q]] = touches[id[q]] || footprint[r]; });
  for (std::size_t q = 0; q < m; ++q)
    if (id[q] >= 0 && touches[id[q]])
      footprint[q] = 1;

  // Within a pixel of the footprint in each slice, as it was counted.
  footprint = amVoxel::Dilate26(plane, footprint, 1);
  std::vector<std::size_t> voxel;
  for (int s = 0; s < slices; ++s)
  {
    amVoxel::SliceVoxels(g, axis, s, voxel);
    for (std::size_t q = 0; q < m; ++q)
      table[voxel[q]] = footprint[q] && !air[voxel[q]];
  }
  return table;
}
