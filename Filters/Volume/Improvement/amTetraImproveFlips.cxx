#include "amTetraImproveMesh.h"

#include <cmath>
#include <limits>

namespace amTetraImprove
{
void Replace(Mesh& m, const std::vector<int>& killed, const std::vector<Tet>& made, int region)
{
  for (int t : killed)
    m.Kill(t);
  for (const Tet& t : made)
    m.Add(t, region);
}

bool RemoveEdge(Mesh& m, int u, int v, int maxRing, std::vector<int>& tets, std::vector<int>& ring)
{
  thread_local std::vector<Tet> made;
  if (!PlanEdgeRemoval(m, u, v, maxRing, tets, ring, made))
    return false;
  Replace(m, tets, made, m.R[tets[0]]);
  return true;
}

bool PlanEdgeRemoval(
  const Mesh& m, int u, int v, int maxRing, std::vector<int>& tets, std::vector<int>& ring, std::vector<Tet>& made)
{
  if (m.FixedEdges.count(EdgeKey(u, v)) || !m.Ring(u, v, tets, ring, static_cast<size_t>(std::max(maxRing, 0))))
    return false;
  const int n = static_cast<int>(ring.size());
  if (n > maxRing)
    return false;
  double old = std::numeric_limits<double>::infinity();
  for (int t : tets)
    old = std::min(old, m.Objectives[t]);
  // best[i][j]: the best worst quality triangulating ring[i..j] (with chord i-j), via k.
  constexpr int N = 16;
  double best[N][N];
  int via[N][N];
  for (int i = 0; i + 1 < n; ++i)
    best[i][i + 1] = std::numeric_limits<double>::infinity();
  for (int len = 2; len < n; ++len)
    for (int i = 0; i + len < n; ++i)
    {
      const int j = i + len;
      best[i][j] = -std::numeric_limits<double>::infinity();
      via[i][j] = -1;
      // A chord that is an edge of the mesh already (through a tetrahedron outside the ring)
      // would give the new tetrahedra a face the mesh has: they would fold over that one.
      if (j - i < n - 1 && m.Connected(ring[i], ring[j]))
        continue;
      for (int k = i + 1; k < j; ++k)
      {
        double q = std::min(best[i][k], best[k][j]);
        if (q <= best[i][j] || q <= old)
          continue;
        q = std::min(q, m.Quality(ring[i], ring[k], ring[j], v));
        if (q <= best[i][j] || q <= old)
          continue;
        q = std::min(q, m.Quality(ring[i], ring[j], ring[k], u));
        if (q > best[i][j])
        {
          best[i][j] = q;
          via[i][j] = k;
        }
      }
    }
  if (!(best[0][n - 1] > old + 1e-12) || via[0][n - 1] < 0)
    return false;
  thread_local std::vector<std::array<int, 2>> todo;
  todo.assign(1, { 0, n - 1 });
  made.clear();
  while (!todo.empty())
  {
    const auto s = todo.back();
    todo.pop_back();
    if (s[1] - s[0] < 2)
      continue;
    const int k = via[s[0]][s[1]];
    made.push_back({ ring[s[0]], ring[k], ring[s[1]], v });
    made.push_back({ ring[s[0]], ring[s[1]], ring[k], u });
    todo.push_back({ s[0], k });
    todo.push_back({ k, s[1] });
  }
  return true;
}

bool Flip23(Mesh& m, int t, int i)
{
  int other;
  thread_local std::vector<Tet> made;
  if (!PlanFlip23(m, t, i, other, made))
    return false;
  Replace(m, { t, other }, made, m.R[t]);
  return true;
}

bool PlanFlip23(const Mesh& m, int t, int i, int& other, std::vector<Tet>& made)
{
  const Tet& x = m.T[t];
  const int d = x[i], a = x[(i + 1) % 4], b = x[(i + 2) % 4], c = x[(i + 3) % 4];
  if (m.FixedFaces.count(Sorted(a, b, c)))
    return false;
  other = m.Across(t, i);
  if (other < 0 || m.R[other] != m.R[t])
    return false;
  int e = -1;
  for (int w : m.T[other])
    if (w != a && w != b && w != c)
      e = w;
  if (e < 0 || m.Connected(d, e))
    return false;
  std::array<int, 3> ring{ { a, b, c } };
  if (amTetraGeometry::SignedVolume(m.X(d), m.X(e), m.X(a), m.X(b)) < 0)
    std::swap(ring[1], ring[2]);
  const double old = std::min(m.Objectives[t], m.Objectives[other]);
  double q = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
    q = std::min(q, m.Quality(d, e, ring[k], ring[(k + 1) % 3]));
  if (!(q > old + 1e-12))
    return false;
  made.clear();
  for (int k = 0; k < 3; ++k)
    made.push_back({ d, e, ring[k], ring[(k + 1) % 3] });
  return true;
}
}
