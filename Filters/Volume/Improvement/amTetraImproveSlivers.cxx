#include "amTetraImproveMesh.h"
#include "amTetraImproveSchedule.h"

#include "amMeshQuality.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amTetraImprove
{
double SliverClear(const Options& options)
{
  // The objective bounds both: 1/Q, and the smallest sine of the dihedral angles over the
  // regular tetrahedron's (a sine above sin(SliverDihedral) keeps every angle in its range).
  const double pi = 3.14159265358979323846;
  return std::max(1.0 / options.SliverQuality, std::sin(options.SliverDihedral * pi / 180.0) * 3.0 / std::sqrt(8.0));
}

bool IsSliver(const Mesh& m, int t, const Options& options)
{
  if (m.Objectives[t] >= SliverClear(options))
    return false;
  double q, minDihedral, maxDihedral, radiusRatio, volume;
  amMeshQuality::TetraQuality(
    m.X(m.T[t][0]), m.X(m.T[t][1]), m.X(m.T[t][2]), m.X(m.T[t][3]), q, minDihedral, maxDihedral, radiusRatio, volume);
  return !(q <= options.SliverQuality && minDihedral >= options.SliverDihedral);
}

long CountSlivers(const Mesh& m, const Options& options)
{
  long count = 0;
  for (size_t t = 0; t < m.T.size(); ++t)
    count += m.Alive[t] && IsSliver(m, static_cast<int>(t), options);
  return count;
}

namespace
{
/// The surface edges of tetrahedron t to split, best first: the one where its dihedral angle is
/// smallest (its midpoint, on the surface, may then slide where the surface is flat and turn
/// that edge), then the longest.
std::vector<std::pair<int, int>> FixedEdgesToSplit(const Mesh& m, int t)
{
  using G = amTetraGeometry;
  static const int edges[6][4] = { { 0, 1, 2, 3 }, { 0, 2, 1, 3 }, { 0, 3, 1, 2 }, { 1, 2, 0, 3 }, { 1, 3, 0, 2 },
    { 2, 3, 0, 1 } };
  const Tet& x = m.T[t];
  std::pair<int, int> sharpest{ -1, -1 }, longest{ -1, -1 };
  double largestCosine = -2, longestLength = 0;
  for (const auto& e : edges)
  {
    const int a = x[e[0]], b = x[e[1]];
    if (!m.FixedEdges.count(EdgeKey(a, b)))
      continue;
    const Vec ab = G::Sub(m.X(b), m.X(a));
    const Vec n1 = G::Cross(ab, G::Sub(m.X(x[e[2]]), m.X(a))), n2 = G::Cross(ab, G::Sub(m.X(x[e[3]]), m.X(a)));
    const double cosine = G::Dot(n1, n2) / (G::Norm(n1) * G::Norm(n2) + 1e-300); // of the dihedral angle
    if (cosine > largestCosine)
    {
      largestCosine = cosine;
      sharpest = { a, b };
    }
    if (G::Norm(ab) > longestLength)
    {
      longestLength = G::Norm(ab);
      longest = { a, b };
    }
  }
  std::vector<std::pair<int, int>> order;
  if (sharpest.first >= 0)
    order.push_back(sharpest);
  if (longest != sharpest)
    order.push_back(longest);
  return order;
}

/// How far the vertices of x have moved from where the surface was (the most of the four): the
/// surface on its faces has moved at most that far.
double Moved(const Mesh& m, const Tet& x)
{
  double most = 0;
  for (int v : x)
  {
    const double* o = &m.Origin[3 * static_cast<size_t>(v)];
    if (!std::isnan(o[0]))
      most = std::max(most, amTetraGeometry::Norm(amTetraGeometry::Sub(m.X(v), o)));
  }
  return most;
}

/// Collapses a surface edge of sliver t, the shortest that collapses (either way) within
/// maxDeviation: the displacement, or -1.
double CollapseShortest(Mesh& m, int t, double maxDeviation, std::unordered_map<int, long>& regionCount)
{
  const Tet x = m.T[t];
  std::vector<std::pair<double, std::pair<int, int>>> edges;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (m.FixedEdges.count(EdgeKey(x[i], x[j])))
      {
        const Vec d = amTetraGeometry::Sub(m.X(x[i]), m.X(x[j]));
        edges.push_back({ amTetraGeometry::Dot(d, d), { x[i], x[j] } });
      }
  std::sort(edges.begin(), edges.end());
  for (const auto& e : edges)
    for (const auto& vu : { e.second, std::make_pair(e.second.second, e.second.first) })
    {
      const double moved = CollapseSurfaceEdge(m, vu.first, vu.second, maxDeviation, regionCount);
      if (moved >= 0)
        return moved;
    }
  return -1;
}

/// The rounds of one attempt with the given budget (mm): slivers' surface vertices slide (three
/// quarters of it), slivers still bad change region (once each, within what the budget leaves
/// where their vertices slid), a surface edge of those left is split, then the flips and moves
/// run again. 'first' Relabel: slivers change region before any slide too (a fin's element,
/// removed while the whole budget is left there, before slides around it spend it); Collapse: a
/// short surface edge of each sliver collapses before any slide (where a junction curve zigzags,
/// or a vertex inside an interface sits next to one, no element spans the place well).
void Attempt(Mesh& m, const Options& options, double budget, First first, Report& report,
  const std::function<void(int)>& improve, const std::function<void()>& fixEdges)
{
  std::unordered_map<int, long> regionCount;
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
      ++regionCount[m.R[t]];
  const double slide = SliverSchedule::SlideShare * budget;
  std::unordered_set<int> relabelled; // once each: a sliver handed back and forth frees nothing
  const double goal = SliverSchedule::GoalMargin * SliverClear(options);
  for (int round = 1; round <= options.SliverRounds; ++round)
  {
    long changes = 0;
    const size_t limit = m.T.size();
    auto relabel = [&]() {
      for (size_t t = 0; t < limit; ++t)
        if (m.Alive[t] && IsSliver(m, static_cast<int>(t), options) && !relabelled.count(static_cast<int>(t)) &&
          Relabel(m, static_cast<int>(t), budget - Moved(m, m.T[t]), regionCount) >= 0)
        {
          relabelled.insert(static_cast<int>(t));
          ++report.Relabels;
          ++changes;
        }
    };
    if (first == First::Collapse)
      for (size_t t = 0; t < limit; ++t)
        if (m.Alive[t] && IsSliver(m, static_cast<int>(t), options) &&
          CollapseShortest(m, static_cast<int>(t), budget - Moved(m, m.T[t]), regionCount) >= 0)
        {
          ++report.SurfaceCollapses;
          ++changes;
        }
    if (first == First::Relabel)
      relabel();
    for (size_t t = 0; t < limit; ++t)
      if (m.Alive[t] && IsSliver(m, static_cast<int>(t), options))
        for (int w : Tet(m.T[t]))
          if (m.FixedVertex[w] && !std::isnan(m.Origin[3 * static_cast<size_t>(w)]) && Climb(m, w, slide, goal))
          {
            ++report.SurfaceMoves;
            ++changes;
          }
    relabel();
    for (size_t t = 0; t < limit; ++t)
      if (m.Alive[t] && IsSliver(m, static_cast<int>(t), options))
      {
        for (const auto& e : FixedEdgesToSplit(m, static_cast<int>(t)))
          if (SplitSurfaceEdge(m, e.first, e.second) >= 0)
          {
            ++report.SurfaceSplits;
            ++changes;
            break;
          }
      }
    if (changes == 0)
      break;
    fixEdges();
    improve(round);
  }
}
}

void FreeSlivers(Mesh& m, const Options& options, Report& report, const std::function<void(int)>& improve,
  const std::function<void()>& fixEdges)
{
  const std::vector<Tri> surfaceBefore(m.FixedFaces.begin(), m.FixedFaces.end());
  m.Origin = m.P;
  // The attempts and their budgets: amTetraImproveSchedule.h.
  const std::vector<double> points = m.P;
  const Mesh saved = m;
  const Report savedReport = report;
  std::vector<double> bestPoints;
  Mesh best(bestPoints);
  Report bestReport = savedReport;
  long bestSlivers = -1;
  const double bound = options.MaximumSurfaceDeviation;
  SliverSchedule schedule(bound);
  for (int attempt = 0; attempt < schedule.Attempts(); ++attempt)
  {
    Attempt(m, options, schedule.Budget(), schedule.Order(attempt), report, improve, fixEdges);
    const double deviation = SurfaceDeviation(m, surfaceBefore);
    const long slivers = CountSlivers(m, options);
    if (deviation <= bound)
    {
      report.SurfaceDeviation = deviation;
      if (slivers == 0)
        return; // the first budget that frees every sliver within the bound
      if (bestSlivers < 0 || slivers < bestSlivers)
      {
        bestSlivers = slivers;
        bestPoints = m.P;
        best.Assign(m);
        bestReport = report;
      }
    }
    if (attempt == schedule.Attempts() - 1)
      break;
    schedule.Record(attempt, deviation);
    m.P = points;
    m.Assign(saved);
    report = savedReport;
  }
  if (bestSlivers >= 0)
  {
    m.P = bestPoints;
    m.Assign(best);
    report = bestReport;
  }
  else
  {
    m.P = points;
    m.Assign(saved);
    report = savedReport;
  }
}
}
