#include "amTetraImproveMesh.h"

#include <cmath>
#include <limits>

namespace amTetraImprove
{
/// The star of v as it is: its worst objective and the sum of the inverse objectives.
void CurrentStar(const Mesh& m, int v, double& worst, double& sum)
{
  worst = std::numeric_limits<double>::infinity();
  sum = 0;
  for (int t : m.Inc[v])
  {
    worst = std::min(worst, m.Objectives[t]);
    sum += 1.0 / m.Objectives[t];
  }
}

/// The star of v with v moved to x: its worst objective and the sum of the inverse objectives
/// (inf when a tetrahedron inverts). The evaluation stops at the first tetrahedron worse than
/// 'floor' or once the sum reaches 'ceiling' (every term is positive, so it only grows): then the
/// candidate is refused whatever the rest of the star, and most candidates are.
void StarQuality(
  const Mesh& m, int v, const double* x, double& worst, double& sumQ, double floor, double ceiling, double* each)
{
  worst = std::numeric_limits<double>::infinity();
  sumQ = 0;
  for (int t : m.Inc[v])
  {
    const double* p[4];
    for (int k = 0; k < 4; ++k)
      p[k] = m.T[t][k] == v ? x : m.X(m.T[t][k]);
    const double q = Objective(p[0], p[1], p[2], p[3]);
    if (each)
      *each++ = q;
    worst = std::min(worst, q);
    if (q <= 0)
    {
      sumQ = std::numeric_limits<double>::infinity();
      return;
    }
    sumQ += 1.0 / q;
    if (q < floor || sumQ >= ceiling)
      return;
  }
}

void PlaceVertex(Mesh& m, int v, const double* x, const double* q)
{
  std::copy(x, x + 3, &m.P[3 * static_cast<size_t>(v)]);
  for (int t : m.Inc[v])
  {
    // The same Objective on the same corners in the same order: the same value as computed anew.
    m.Objectives[t] = q ? *q++ : m.Quality(m.T[t][0], m.T[t][1], m.T[t][2], m.T[t][3]);
    m.Tried[t] = 0;
  }
}

void MarkStarDirty(Mesh& m, int v)
{
  for (int t : m.Inc[v])
    for (int w : m.T[t])
      m.Dirty[w] = 1;
}

void MoveVertex(Mesh& m, int v, const double* x, const double* q)
{
  PlaceVertex(m, v, x, q);
  MarkStarDirty(m, v);
}

bool SmoothTarget(const Mesh& m, int v, double* bestPos, double* bestQ)
{
  const auto& inc = m.Inc[v];
  if (inc.empty())
    return false;
  const double* x = m.X(v);
  double worst0, sum0;
  CurrentStar(m, v, worst0, sum0);
  double centroid[3] = { 0, 0, 0 }, mass = 0, neighbours[3] = { 0, 0, 0 };
  int count = 0;
  for (int t : inc)
  {
    const Tet& s = m.T[t];
    const double vol = std::fabs(amTetraGeometry::SignedVolume(m.X(s[0]), m.X(s[1]), m.X(s[2]), m.X(s[3])));
    for (int d = 0; d < 3; ++d)
      centroid[d] += vol * (m.X(s[0])[d] + m.X(s[1])[d] + m.X(s[2])[d] + m.X(s[3])[d]) / 4;
    mass += vol;
    for (int w : s)
      if (w != v)
      {
        for (int d = 0; d < 3; ++d)
          neighbours[d] += m.X(w)[d];
        ++count;
      }
  }
  if (!(mass > 0) || count == 0)
    return false;
  double targets[2][3];
  for (int d = 0; d < 3; ++d)
  {
    targets[0][d] = centroid[d] / mass;
    targets[1][d] = neighbours[d] / count;
  }
  double bestSum = sum0 * (1 - 1e-9);
  bool found = false;
  // A candidate taken was evaluated whole (an early stop refuses it): its objectives are the
  // star's at its position.
  thread_local std::vector<double> each;
  if (bestQ)
    each.resize(inc.size());
  for (const auto& target : targets)
    for (double f : { 1.0, 0.5, 0.25 })
    {
      double y[3];
      for (int d = 0; d < 3; ++d)
        y[d] = x[d] + f * (target[d] - x[d]);
      double worst, sum;
      StarQuality(m, v, y, worst, sum, worst0, bestSum, bestQ ? each.data() : nullptr);
      if (worst >= worst0 && sum < bestSum)
      {
        bestSum = sum;
        std::copy(y, y + 3, bestPos);
        if (bestQ)
          std::copy(each.begin(), each.end(), bestQ);
        found = true;
      }
    }
  return found;
}

bool Smooth(Mesh& m, int v)
{
  double y[3];
  if (!SmoothTarget(m, v, y))
    return false;
  MoveVertex(m, v, y);
  return true;
}

/// Local search: moves v along the numerical gradient of its star's worst quality (with a finite
/// radius, within StarDeviation of the surface as it was), until that reaches 'goal'.
bool Climb(Mesh& m, int v, double radius, double goal)
{
  const auto& inc = m.Inc[v];
  if (inc.empty())
    return false;
  double length = 0;
  int count = 0;
  for (int t : inc)
    for (int w : m.T[t])
      if (w != v)
      {
        length += amTetraGeometry::Norm(amTetraGeometry::Sub(m.X(w), m.X(v)));
        ++count;
      }
  length /= std::max(count, 1);
  bool moved = false;
  for (int iteration = 0; iteration < 12; ++iteration)
  {
    double x[3];
    std::copy(m.X(v), m.X(v) + 3, x);
    // The worst tetrahedron of the star and the gradient of its quality.
    int active = -1;
    for (int t : inc)
      if (active < 0 || m.Objectives[t] < m.Objectives[active])
        active = t;
    const double worst0 = m.Objectives[active];
    if (worst0 >= goal)
      break;
    const double h = 1e-5 * length;
    double g[3];
    for (int d = 0; d < 3; ++d)
    {
      double y[3] = { x[0], x[1], x[2] };
      const double* p[4];
      double f[2];
      for (int s = 0; s < 2; ++s)
      {
        y[d] = x[d] + (s ? h : -h);
        for (int k = 0; k < 4; ++k)
          p[k] = m.T[active][k] == v ? y : m.X(m.T[active][k]);
        f[s] = Objective(p[0], p[1], p[2], p[3]);
      }
      g[d] = (f[1] - f[0]) / (2 * h);
    }
    const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (!(norm > 0))
      break;
    bool improved = false;
    for (double step = 0.2 * length; step > 1e-4 * length && !improved; step *= 0.5)
    {
      double y[3];
      for (int d = 0; d < 3; ++d)
        y[d] = x[d] + step * g[d] / norm;
      if (radius < std::numeric_limits<double>::infinity() && !(StarDeviation(m, v, y) <= radius))
        continue;
      double worst, sum;
      StarQuality(m, v, y, worst, sum, worst0 + 1e-12);
      if (worst > worst0 + 1e-12)
      {
        MoveVertex(m, v, y);
        improved = moved = true;
      }
    }
    if (!improved)
      break;
  }
  return moved;
}
}
