#include "amTetraImproveMesh.h"

#include <cmath>
#include <limits>

namespace amTetraImprove
{
/// Splits the free edge (u, v) at its midpoint, then moves the new vertex where its star is best:
/// the one remedy for a sliver whose vertices all lie on the surface (no flip helps there).
/// Undone unless every element around the new vertex reaches 'goal' (a split that only spreads a
/// surface-bound sliver over several bad elements is worse than the sliver).
bool SplitEdge(Mesh& m, int u, int v, double goal, std::vector<int>& tets, std::vector<int>& ring)
{
  if (m.FixedEdges.count(EdgeKey(u, v)) || !m.Ring(u, v, tets, ring))
    return false;
  double old = std::numeric_limits<double>::infinity();
  for (int t : tets)
    old = std::min(old, m.Objectives[t]);
  const double mid[3] = { 0.5 * (m.X(u)[0] + m.X(v)[0]), 0.5 * (m.X(u)[1] + m.X(v)[1]), 0.5 * (m.X(u)[2] + m.X(v)[2]) };
  const int w = m.AddPoint(mid);
  const int region = m.R[tets[0]];
  std::vector<Tet> before;
  for (int t : tets)
  {
    before.push_back(m.T[t]);
    m.Kill(t);
  }
  const int n = static_cast<int>(ring.size());
  for (int i = 0; i < n; ++i)
  {
    m.Add({ u, w, ring[i], ring[(i + 1) % n] }, region);
    m.Add({ w, v, ring[i], ring[(i + 1) % n] }, region);
  }
  return KeepInsertion(m, w, before, region, old, goal);
}

bool KeepInsertion(Mesh& m, int w, const std::vector<Tet>& before, int region, double old, double goal)
{
  Climb(m, w);
  Smooth(m, w);
  double now = std::numeric_limits<double>::infinity();
  for (int t : m.Inc[w])
    now = std::min(now, m.Objectives[t]);
  if (now > old + 1e-12 && now >= goal)
    return true;
  const std::vector<int> made = m.Inc[w];
  for (int t : made)
    m.Kill(t);
  for (const Tet& t : before)
    m.Add(t, region);
  m.FixedVertex[w] = 1; // unused from now on
  return false;
}
}
