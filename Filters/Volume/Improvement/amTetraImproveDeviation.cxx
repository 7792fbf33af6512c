#include "amTetraImproveMesh.h"

#include "amTriangleLocator.h"

#include <cmath>
#include <limits>
#include <unordered_set>

namespace amTetraImprove
{
namespace
{
/// The triangles 'tris' on the positions 'points' (3 doubles a vertex) for a locator: the vertices
/// they use are copied, renumbered.
void Locate(amTriangleLocator& locator, const std::vector<Tri>& tris, const double* points)
{
  std::vector<std::array<double, 3>> corners;
  std::vector<std::array<vtkIdType, 3>> triangles;
  corners.reserve(3 * tris.size());
  for (const Tri& t : tris)
  {
    std::array<vtkIdType, 3> ids;
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = static_cast<vtkIdType>(corners.size());
      const double* x = points + 3 * static_cast<size_t>(t[k]);
      corners.push_back({ { x[0], x[1], x[2] } });
    }
    triangles.push_back(ids);
  }
  locator.Build(corners, triangles);
}

/// The largest distance from the sampled points of 'from' (on 'fromPoints') to the locator's set.
double Farthest(const std::vector<Tri>& from, const double* fromPoints, const amTriangleLocator& to)
{
  double worst = 0, closest[3];
  vtkIdType triangle;
  for (const Tri& t : from)
    SampleTriangle(fromPoints + 3 * static_cast<size_t>(t[0]), fromPoints + 3 * static_cast<size_t>(t[1]),
      fromPoints + 3 * static_cast<size_t>(t[2]), 8,
      [&](const double* x) { worst = std::max(worst, to.ClosestPoint(x, closest, triangle)); });
  return std::sqrt(worst);
}
}

double FarthestPoint(const Mesh& m, const Tri& f, const std::vector<Tri>& to)
{
  if (to.empty())
    return std::numeric_limits<double>::infinity();
  double worst = 0, closest[3];
  SampleTriangle(m.X(f[0]), m.X(f[1]), m.X(f[2]), 8, [&](const double* x) {
    double best = std::numeric_limits<double>::infinity();
    for (const Tri& g : to)
      best = std::min(best, amTriangleLocator::ClosestPointOnTriangle(x, m.X(g[0]), m.X(g[1]), m.X(g[2]), closest));
    worst = std::max(worst, best);
  });
  return std::sqrt(worst);
}

double StarDeviation(const Mesh& m, int v, const double* y)
{
  // The fixed faces around v, on the positions now (v at y) and on the original ones.
  std::vector<Tri> star;
  for (int t : m.Inc[v])
    for (int i = 0; i < 4; ++i)
    {
      const Tet& x = m.T[t];
      if (x[i] == v)
        continue;
      const Tri f = Sorted(x[(i + 1) % 4], x[(i + 2) % 4], x[(i + 3) % 4]);
      if (m.FixedFaces.count(f) && std::find(star.begin(), star.end(), f) == star.end())
        star.push_back(f);
    }
  if (static_cast<size_t>(v) >= m.Origin.size() / 3 || std::isnan(m.Origin[3 * static_cast<size_t>(v)]))
    return std::numeric_limits<double>::infinity();
  auto now = [&](int w) { return w == v ? y : m.X(w); };
  auto then = [&](int w) { return w == v ? &m.Origin[3 * static_cast<size_t>(w)] : m.X(w); };
  double worst = 0, closest[3];
  for (int side = 0; side < 2; ++side)
    for (const Tri& f : star)
    {
      const double *a = side ? then(f[0]) : now(f[0]), *b = side ? then(f[1]) : now(f[1]),
                   *c = side ? then(f[2]) : now(f[2]);
      SampleTriangle(a, b, c, 4, [&](const double* x) {
        double best = std::numeric_limits<double>::infinity();
        for (const Tri& g : star)
          best = std::min(best,
            amTriangleLocator::ClosestPointOnTriangle(
              x, side ? now(g[0]) : then(g[0]), side ? now(g[1]) : then(g[1]), side ? now(g[2]) : then(g[2]), closest));
        worst = std::max(worst, best);
      });
    }
  return std::sqrt(worst);
}

double SurfaceDeviation(const Mesh& m, const std::vector<Tri>& before)
{
  const size_t original = m.Origin.size() / 3;
  auto moved = [&](int v) {
    return static_cast<size_t>(v) >= original || std::isnan(m.Origin[3 * v]) || m.X(v)[0] != m.Origin[3 * v] ||
      m.X(v)[1] != m.Origin[3 * v + 1] || m.X(v)[2] != m.Origin[3 * v + 2];
  };
  std::unordered_set<Tri, TriHash> old;
  for (const Tri& t : before)
    old.insert(Sorted(t[0], t[1], t[2]));
  std::vector<Tri> now(m.FixedFaces.begin(), m.FixedFaces.end());
  std::sort(now.begin(), now.end());
  std::vector<Tri> gone, made;
  for (const Tri& t : before)
    if (!m.FixedFaces.count(Sorted(t[0], t[1], t[2])) || moved(t[0]) || moved(t[1]) || moved(t[2]))
      gone.push_back(t);
  for (const Tri& t : now)
    if (!old.count(t) || moved(t[0]) || moved(t[1]) || moved(t[2]))
      made.push_back(t);
  if (gone.empty() && made.empty())
    return 0;
  amTriangleLocator beforeLocator, nowLocator;
  Locate(beforeLocator, before, m.Origin.data());
  Locate(nowLocator, now, m.P.data());
  return std::max(Farthest(made, m.P.data(), beforeLocator), Farthest(gone, m.Origin.data(), nowLocator));
}
}
