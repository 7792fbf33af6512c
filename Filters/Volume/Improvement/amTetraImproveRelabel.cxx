#include "amTetraImproveMesh.h"

#include <cmath>
#include <limits>

namespace amTetraImprove
{
namespace
{
Tri Face(const Tet& x, int i)
{
  return Sorted(x[(i + 1) % 4], x[(i + 2) % 4], x[(i + 3) % 4]);
}
}

/// Gives the tetrahedron t the region of a neighbour across one of its fixed faces, or removes it
/// when that face is on the mesh's boundary: the faces it shared with that region leave the
/// surface and those it shared with its own region join it. A sliver whose faces lie on the
/// surface (a wedge between two interfaces at a junction curve, a flat element under a surface
/// triangle) has no flip or free vertex to mend it; once on the other side of the surface, its
/// faces are free and the flips and moves of that region can remove it. The surface moves by the
/// element's thickness; the candidate that moves it least is taken, when that is at most
/// maxDeviation and the region keeps other tetrahedra. Returns the deviation, or -1.
double Relabel(Mesh& m, int t, double maxDeviation, std::unordered_map<int, long>& regionCount)
{
  const Tet x = m.T[t];
  const int own = m.R[t];
  if (regionCount[own] <= 1)
    return -1;
  int across[4];
  for (int i = 0; i < 4; ++i)
    across[i] = m.Across(t, i);
  constexpr int background = std::numeric_limits<int>::min();
  auto regionOf = [&](int s) { return s < 0 ? background : m.R[s]; };
  double bestDeviation = std::numeric_limits<double>::infinity();
  int bestRegion = own;
  for (int i = 0; i < 4; ++i)
  {
    const int target = regionOf(across[i]);
    if (target == own || target == bestRegion || !m.FixedFaces.count(Face(x, i)))
      continue;
    // Faces leaving the surface, joining it, and staying (towards a third region).
    std::vector<Tri> leave, join, stay;
    for (int k = 0; k < 4; ++k)
    {
      const int r = regionOf(across[k]);
      (r == target ? leave : r == own ? join : stay).push_back(Face(x, k));
    }
    std::vector<Tri> newSide = join, oldSide = leave;
    newSide.insert(newSide.end(), stay.begin(), stay.end());
    oldSide.insert(oldSide.end(), stay.begin(), stay.end());
    double deviation = 0;
    for (const Tri& f : join)
      deviation = std::max(deviation, FarthestPoint(m, f, oldSide));
    for (const Tri& f : leave)
      deviation = std::max(deviation, FarthestPoint(m, f, newSide));
    if (deviation < bestDeviation)
    {
      bestDeviation = deviation;
      bestRegion = target;
    }
  }
  if (bestRegion == own || !(bestDeviation <= maxDeviation))
    return -1;
  for (int k = 0; k < 4; ++k)
  {
    const Tri f = Face(x, k);
    const int r = regionOf(across[k]);
    if (r == bestRegion)
      m.FixedFaces.erase(f);
    else if (bestRegion != background || r != background)
      m.FixedFaces.insert(f);
    else
      m.FixedFaces.erase(f); // a face with nothing on either side
  }
  --regionCount[own];
  if (bestRegion == background)
    m.Kill(t);
  else
  {
    m.R[t] = bestRegion;
    ++regionCount[bestRegion];
  }
  for (int v : x)
  {
    if (!m.FixedVertex[v] && !m.Origin.empty()) // on the surface from now on, where it is now
      std::copy(m.X(v), m.X(v) + 3, &m.Origin[3 * static_cast<size_t>(v)]);
    m.FixedVertex[v] = 1;
    m.Dirty[v] = 1;
    for (int s : m.Inc[v]) // their faces may be free now: flips may mend them
      m.Tried[s] = 0;
  }
  return bestDeviation;
}
}
