#include "amTetraImproveMesh.h"

#include "amTriangleLocator.h"

#include <cmath>
#include <limits>
#include <utility>

namespace amTetraImprove
{
namespace
{
using Interface = std::pair<int, int>;
constexpr int Background = std::numeric_limits<int>::min();

Tri Face(const Tet& x, int i)
{
  return Sorted(x[(i + 1) % 4], x[(i + 2) % 4], x[(i + 3) % 4]);
}

bool Holds(const Tri& f, int v)
{
  return f[0] == v || f[1] == v || f[2] == v;
}

/// The interfaces (the two regions, the mesh's outside as one) of the fixed faces around v;
/// with 'edge' >= 0, only of those holding the edge (v, edge).
std::vector<Interface> InterfacesAt(const Mesh& m, int v, int edge)
{
  std::vector<Interface> out;
  for (int t : m.Inc[v])
    for (int i = 0; i < 4; ++i)
    {
      const Tet& x = m.T[t];
      if (x[i] == v || (edge >= 0 && x[i] == edge) || (edge >= 0 && !m.Has(t, edge)))
        continue;
      if (!m.FixedFaces.count(Face(x, i)))
        continue;
      const int s = m.Across(t, i);
      const Interface p = std::minmax(m.R[t], s < 0 ? Background : m.R[s]);
      if (std::find(out.begin(), out.end(), p) == out.end())
        out.push_back(p);
    }
  return out;
}

/// Whether some tetrahedron around a holds b, c (c < 0: b alone) and d (d < 0: none).
bool Around(const Mesh& m, int a, int b, int c, int d = -1)
{
  for (int t : m.Inc[a])
    if (m.Has(t, b) && (c < 0 || m.Has(t, c)) && (d < 0 || m.Has(t, d)))
      return true;
  return false;
}

/// The faces of the mesh's boundary (of one tetrahedron) around w.
std::vector<Tri> BoundaryFacesAt(const Mesh& m, int w)
{
  std::vector<Tri> out;
  for (int t : m.Inc[w])
    for (int i = 0; i < 4; ++i)
      if (m.T[t][i] != w && m.Across(t, i) < 0)
        out.push_back(Face(m.T[t], i));
  return out;
}

/// The link condition of the edge (u, v), which keeps the mesh a manifold through the collapse:
/// a vertex next to both is on a tetrahedron of the edge, and an edge that makes a triangle with
/// each bounds a tetrahedron with the edge; with the outside as one more vertex joined to the
/// boundary, both on the boundary only along a boundary edge, and a vertex joined to both by
/// boundary edges only in a boundary face with them.
bool LinkCondition(const Mesh& m, int u, int v)
{
  const std::vector<Tri> bu = BoundaryFacesAt(m, u), bv = BoundaryFacesAt(m, v);
  if (!bu.empty() && !bv.empty())
  {
    bool edge = false;
    for (const Tri& f : bv)
      edge = edge || Holds(f, u);
    if (!edge)
      return false;
    for (const Tri& f : bv)
      for (int w : f)
      {
        if (w == v || w == u)
          continue;
        bool joined = false, face = false;
        for (const Tri& g : bu)
          joined = joined || Holds(g, w);
        for (const Tri& g : bv)
          face = face || (Holds(g, u) && Holds(g, w));
        if (joined && !face)
          return false;
      }
  }
  for (int t : m.Inc[v])
  {
    if (m.Has(t, u))
      continue;
    const Tet& x = m.T[t];
    for (int i = 0; i < 4; ++i)
    {
      const int w = x[i];
      if (w == v)
        continue;
      if (Around(m, u, w, -1) && !Around(m, u, v, w))
        return false;
      for (int j = i + 1; j < 4; ++j)
        if (x[j] != v && Around(m, u, w, x[j]) && !Around(m, u, v, w, x[j]))
          return false;
    }
  }
  return true;
}

/// The largest distance from the sampled points of the triangles 'from' to the set 'to'.
double Farthest(const Mesh& m, const std::vector<Tri>& from, const std::vector<Tri>& to)
{
  double worst = 0;
  for (const Tri& f : from)
    worst = std::max(worst, FarthestPoint(m, f, to));
  return worst;
}

/// The fixed faces holding vertex w.
std::vector<Tri> FixedFacesAt(const Mesh& m, int w)
{
  std::vector<Tri> out;
  for (int t : m.Inc[w])
    for (int i = 0; i < 4; ++i)
    {
      const Tri f = Face(m.T[t], i);
      if (m.T[t][i] != w && m.FixedFaces.count(f) && std::find(out.begin(), out.end(), f) == out.end())
        out.push_back(f);
    }
  return out;
}
}

double CollapseSurfaceEdge(Mesh& m, int v, int u, double maxDeviation, std::unordered_map<int, long>& regionCount)
{
  if (u == v || !m.FixedVertex[v] || m.Inc[v].empty() || !m.FixedEdges.count(EdgeKey(u, v)) || !m.Connected(u, v))
    return -1;
  // v's interfaces all on the edge: a vertex inside an interface moves along it, one on a
  // junction curve along that curve, and a corner where curves meet stays.
  const std::vector<Interface> atV = InterfacesAt(m, v, -1), onEdge = InterfacesAt(m, v, u);
  for (const Interface& p : atV)
    if (std::find(onEdge.begin(), onEdge.end(), p) == onEdge.end())
      return -1;
  if (!LinkCondition(m, u, v))
    return -1;
  // The elements after: v's replaced by u, none inverted, the worst better than before, every
  // region keeping an element.
  double before = std::numeric_limits<double>::infinity(), after = before;
  for (int t : m.Inc[u])
  {
    before = std::min(before, m.Objectives[t]);
    if (!m.Has(t, v))
      after = std::min(after, m.Objectives[t]);
  }
  std::vector<std::pair<Tet, int>> made;
  std::unordered_map<int, long> lost;
  for (int t : m.Inc[v])
  {
    before = std::min(before, m.Objectives[t]);
    if (m.Has(t, u))
    {
      if (++lost[m.R[t]] >= regionCount[m.R[t]])
        return -1;
      continue;
    }
    Tet x = m.T[t];
    std::replace(x.begin(), x.end(), v, u);
    after = std::min(after, m.Quality(x[0], x[1], x[2], x[3]));
    made.push_back({ x, m.R[t] });
  }
  if (!(after > before))
    return -1;
  // Made, then measured: the surface around u is the faces between two regions there (where a
  // fin of a region between two others closes, the two meet).
  std::vector<Tri> old = FixedFacesAt(m, u);
  for (const Tri& f : FixedFacesAt(m, v))
    if (std::find(old.begin(), old.end(), f) == old.end())
      old.push_back(f);
  const std::vector<int> star = m.Inc[v];
  for (int t : star)
    m.Kill(t);
  std::vector<int> added;
  for (const auto& x : made)
    added.push_back(m.Add(x.first, x.second));
  std::vector<std::pair<Tri, bool>> changed; // a face, and whether it was fixed before
  auto set = [&](const Tri& f, bool fixed) {
    const bool was = m.FixedFaces.count(f) > 0;
    if (was == fixed)
      return;
    changed.push_back({ f, was });
    if (fixed)
      m.FixedFaces.insert(f);
    else
      m.FixedFaces.erase(f);
  };
  for (const Tri& f : old)
    if (Holds(f, v))
      set(f, false);
  for (int t : m.Inc[u])
    for (int i = 0; i < 4; ++i)
      if (m.T[t][i] != u)
      {
        const int s = m.Across(t, i);
        set(Face(m.T[t], i), s < 0 || m.R[s] != m.R[t]);
      }
  const std::vector<Tri> now = FixedFacesAt(m, u);
  const double deviation = std::max(Farthest(m, old, now), Farthest(m, now, old));
  if (!(deviation <= maxDeviation))
  {
    for (int t : added)
      m.Kill(t);
    for (int t : star)
      m.Revive(t);
    for (const auto& c : changed)
      if (c.second)
        m.FixedFaces.insert(c.first);
      else
        m.FixedFaces.erase(c.first);
    return -1;
  }
  for (const auto& l : lost)
    regionCount[l.first] -= l.second;
  for (const auto& c : changed)
    for (int k = 0; k < 3; ++k)
      if (!c.second)
        m.FixedEdges.insert(EdgeKey(c.first[k], c.first[(k + 1) % 3]));
  for (const Tri& f : old) // (the other edges of v's faces stay fixed until FixedEdges is made anew)
    if (Holds(f, v))
      for (int w : f)
        if (w != v)
          m.FixedEdges.erase(EdgeKey(v, w));
  for (int t : m.Inc[u])
  {
    m.Tried[t] = 0;
    for (int w : m.T[t])
      m.Dirty[w] = 1;
  }
  return deviation;
}
}
