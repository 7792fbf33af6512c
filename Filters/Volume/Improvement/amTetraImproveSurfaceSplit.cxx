#include "amTetraImproveMesh.h"

namespace amTetraImprove
{
/// Splits the surface edge (u, v) at its midpoint: every tetrahedron around it, whatever its
/// region, in two, and every fixed face on it in two, so the surface keeps its shape exactly.
/// Near a junction whose interfaces meet at a small angle, no element can be better than that
/// angle allows, and opening it moves the surface in proportion to the elements' size there:
/// smaller elements there need less of the deviation budget. The new vertex is fixed, its origin
/// the midpoint (it may slide where StarDeviation allows). Undone when an element it makes is
/// worse than the worst it replaces. Returns the new vertex, or -1.
int SplitSurfaceEdge(Mesh& m, int u, int v)
{
  std::vector<int> around;
  for (int t : m.Inc[u])
    if (m.Has(t, v))
      around.push_back(t);
  if (around.empty() || !m.FixedEdges.count(EdgeKey(u, v)))
    return -1;
  const double mid[3] = { 0.5 * (m.X(u)[0] + m.X(v)[0]), 0.5 * (m.X(u)[1] + m.X(v)[1]), 0.5 * (m.X(u)[2] + m.X(v)[2]) };
  double worstBefore = 1;
  for (int t : around)
    worstBefore = std::min(worstBefore, m.Objectives[t]);
  const int w = m.AddPoint(mid);
  m.FixedVertex[w] = 1;
  if (!m.Origin.empty())
    std::copy(mid, mid + 3, m.Origin.end() - 3);
  std::vector<Tri> split;
  std::vector<int> made;
  for (int t : around)
  {
    const Tet x = m.T[t];
    const int region = m.R[t];
    for (int i = 0; i < 4; ++i)
    {
      if (x[i] == u || x[i] == v)
        continue;
      // The face opposite x[i] holds the edge when it is not the face opposite u or v.
      const Tri f = Sorted(x[(i + 1) % 4], x[(i + 2) % 4], x[(i + 3) % 4]);
      if (m.FixedFaces.erase(f))
      {
        split.push_back(f);
        const int other = f[0] != u && f[0] != v ? f[0] : f[1] != u && f[1] != v ? f[1] : f[2];
        m.FixedFaces.insert(Sorted(u, w, other));
        m.FixedFaces.insert(Sorted(w, v, other));
      }
    }
    m.Kill(t);
    Tet a = x, b = x;
    for (int k = 0; k < 4; ++k)
    {
      if (x[k] == v)
        a[k] = w;
      if (x[k] == u)
        b[k] = w;
    }
    made.push_back(m.Add(a, region));
    made.push_back(m.Add(b, region));
  }
  // Kept only when no element gets worse than the worst it replaces (a split through a poor
  // element can make a worse one beside it).
  double worstAfter = 1;
  for (int t : made)
    worstAfter = std::min(worstAfter, m.Objectives[t]);
  if (worstAfter < worstBefore)
  {
    for (int t : made)
      m.Kill(t);
    for (int t : around)
      m.Revive(t);
    for (const Tri& f : split)
    {
      const int other = f[0] != u && f[0] != v ? f[0] : f[1] != u && f[1] != v ? f[1] : f[2];
      m.FixedFaces.erase(Sorted(u, w, other));
      m.FixedFaces.erase(Sorted(w, v, other));
      m.FixedFaces.insert(f);
    }
    return -1; // w stays, unused
  }
  m.FixedEdges.erase(EdgeKey(u, v));
  m.FixedEdges.insert(EdgeKey(u, w));
  m.FixedEdges.insert(EdgeKey(w, v));
  return w;
}
}
