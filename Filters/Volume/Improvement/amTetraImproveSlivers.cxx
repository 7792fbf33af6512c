#include "amTetraImproveMesh.h"

#include "amMeshQuality.h"

#include <algorithm>
#include <cmath>

namespace amTetraImprove
{
double SliverClear(const amTetraMeshOptimizer::Options& options)
{
  // The objective bounds both: 1/Q, and the smallest sine of the dihedral angles over the
  // regular tetrahedron's (a sine above sin(SliverDihedral) keeps every angle in its range).
  const double pi = 3.14159265358979323846;
  return std::max(1.0 / options.SliverQuality, std::sin(options.SliverDihedral * pi / 180.0) * 3.0 / std::sqrt(8.0));
}

bool IsSliver(const Mesh& m, int t, const amTetraMeshOptimizer::Options& options)
{
  if (m.Q[t] >= SliverClear(options))
    return false;
  double q, minDihedral, maxDihedral, radiusRatio, volume;
  amMeshQuality::TetraQuality(
    m.X(m.T[t][0]), m.X(m.T[t][1]), m.X(m.T[t][2]), m.X(m.T[t][3]), q, minDihedral, maxDihedral, radiusRatio, volume);
  return !(q <= options.SliverQuality && minDihedral >= options.SliverDihedral);
}

namespace
{
/// The longest surface edge of tetrahedron t, {-1, -1} when none.
std::pair<int, int> LongestFixedEdge(const Mesh& m, int t)
{
  static const int edges[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
  std::pair<int, int> best{ -1, -1 };
  double longest = 0;
  for (const auto& e : edges)
  {
    const int a = m.T[t][e[0]], b = m.T[t][e[1]];
    const double l = amTetraGeometry::Norm(amTetraGeometry::Sub(m.X(a), m.X(b)));
    if (m.FixedEdges.count(EdgeKey(a, b)) && l > longest)
    {
      longest = l;
      best = { a, b };
    }
  }
  return best;
}

/// The rounds of one attempt with the given budget (mm): slivers' surface vertices slide (three
/// quarters of it), slivers still bad change region (the rest), the longest surface edge of those
/// left is split, then the flips and moves run again.
void Attempt(Mesh& m, const amTetraMeshOptimizer::Options& options, double budget, amTetraMeshOptimizer::Report& report,
  const std::function<void(int)>& improve, const std::function<void()>& fixEdges)
{
  std::unordered_map<int, long> regionCount;
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
      ++regionCount[m.R[t]];
  const double slide = 0.75 * budget, relabel = budget - slide;
  const double goal = 1.05 * SliverClear(options); // a margin: the bar is on Q and angles, the goal on the objective
  for (int round = 1; round <= options.SliverRounds; ++round)
  {
    long changes = 0;
    const size_t limit = m.T.size();
    for (size_t t = 0; t < limit; ++t)
      if (m.Alive[t] && IsSliver(m, static_cast<int>(t), options))
        for (int w : Tet(m.T[t]))
          if (m.FixedVertex[w] && !std::isnan(m.Origin[3 * static_cast<size_t>(w)]) && Climb(m, w, slide, goal))
          {
            ++report.SurfaceMoves;
            ++changes;
          }
    for (size_t t = 0; t < limit; ++t)
      if (m.Alive[t] && IsSliver(m, static_cast<int>(t), options) &&
        Relabel(m, static_cast<int>(t), relabel, regionCount) >= 0)
      {
        ++report.Relabels;
        ++changes;
      }
    for (size_t t = 0; t < limit; ++t)
      if (m.Alive[t] && IsSliver(m, static_cast<int>(t), options))
      {
        const auto e = LongestFixedEdge(m, static_cast<int>(t));
        if (e.first >= 0 && SplitSurfaceEdge(m, e.first, e.second) >= 0)
        {
          ++report.SurfaceSplits;
          ++changes;
        }
      }
    if (changes == 0)
      break;
    fixEdges();
    improve(round);
  }
}
}

void FreeSlivers(Mesh& m, const amTetraMeshOptimizer::Options& options, amTetraMeshOptimizer::Report& report,
  const std::function<void(int)>& improve, const std::function<void()>& fixEdges)
{
  const std::vector<Tri> surfaceBefore(m.FixedFaces.begin(), m.FixedFaces.end());
  m.Origin = m.P;
  // The operations bound their own displacement; together they may exceed the budget where
  // several act on one place. The deviation is measured, and the attempt is made again from the
  // same mesh with a smaller budget until it is within MaximumSurfaceDeviation (or left undone).
  const std::vector<double> points = m.P;
  const Mesh saved = m;
  const amTetraMeshOptimizer::Report savedReport = report;
  double budget = options.MaximumSurfaceDeviation;
  for (int attempt = 0; attempt < 4; ++attempt)
  {
    Attempt(m, options, budget, report, improve, fixEdges);
    const double deviation = SurfaceDeviation(m, surfaceBefore);
    if (deviation <= options.MaximumSurfaceDeviation)
    {
      report.SurfaceDeviation = deviation;
      return;
    }
    budget *= 0.9 * options.MaximumSurfaceDeviation / deviation;
    m.P = points;
    m.Assign(saved);
    report = savedReport;
  }
}
}
