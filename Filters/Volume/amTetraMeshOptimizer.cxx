#include "amTetraMeshOptimizer.h"

#include "amMeshQuality.h"
#include "amTetraGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace
{
using Vec = amTetraGeometry::Vec;
using Tet = std::array<int, 4>;
using Tri = std::array<int, 3>;

struct TriHash
{
  size_t operator()(const Tri& k) const
  {
    uint64_t h = 1469598103934665603ull;
    for (int v : k)
      h ^= static_cast<uint64_t>(static_cast<uint32_t>(v)) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};
Tri Sorted(int a, int b, int c)
{
  Tri t{ { a, b, c } };
  std::sort(t.begin(), t.end());
  return t;
}
uint64_t EdgeKey(int a, int b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

/// The mesh being improved: tetrahedra are appended and killed, never moved, so ids stay valid.
class Mesh
{
public:
  std::vector<double>& P;
  std::vector<Tet> T;
  std::vector<int> R;
  std::vector<char> Alive;
  std::vector<double> Q; // Objective per tetrahedron (kept current as vertices move)
  std::vector<char> Tried; // per tetrahedron: the flips failed and nothing moved since
  std::vector<char> Dirty; // per vertex: its star changed since it was last smoothed
  std::vector<std::vector<int>> Inc;
  std::unordered_set<Tri, TriHash> FixedFaces;
  std::unordered_set<uint64_t> FixedEdges;
  std::vector<char> FixedVertex;

  explicit Mesh(std::vector<double>& p)
    : P(p)
  {
  }
  const double* X(int v) const { return &this->P[3 * static_cast<size_t>(v)]; }
  double Quality(int a, int b, int c, int d) const
  {
    return amTetraMeshOptimizer::Objective(this->X(a), this->X(b), this->X(c), this->X(d));
  }
  int AddPoint(const double* x)
  {
    this->P.insert(this->P.end(), x, x + 3);
    this->Inc.emplace_back();
    this->FixedVertex.push_back(0);
    this->Dirty.push_back(1);
    return static_cast<int>(this->Inc.size()) - 1;
  }
  int Add(const Tet& t, int region)
  {
    const int id = static_cast<int>(this->T.size());
    this->T.push_back(t);
    this->R.push_back(region);
    this->Alive.push_back(1);
    this->Q.push_back(this->Quality(t[0], t[1], t[2], t[3]));
    this->Tried.push_back(0);
    for (int v : t)
    {
      this->Inc[v].push_back(id);
      this->Dirty[v] = 1;
    }
    return id;
  }
  void Kill(int id)
  {
    this->Alive[id] = 0;
    for (int v : this->T[id])
    {
      auto& inc = this->Inc[v];
      inc.erase(std::find(inc.begin(), inc.end(), id));
    }
  }
  bool Has(int t, int v) const
  {
    const Tet& x = this->T[t];
    return x[0] == v || x[1] == v || x[2] == v || x[3] == v;
  }
  bool Connected(int a, int b) const
  {
    for (int t : this->Inc[a])
      if (this->Has(t, b))
        return true;
    return false;
  }

  /// The tetrahedra around edge (u, v), ordered, with their ring w such that every tetrahedron
  /// (u, v, w[i], w[i+1]) is positively oriented. False when the ring is not closed.
  bool Ring(int u, int v, std::vector<int>& tets, std::vector<int>& ring) const
  {
    tets.clear();
    ring.clear();
    std::vector<int> around;
    for (int t : this->Inc[u])
      if (this->Has(t, v))
        around.push_back(t);
    if (around.size() < 3)
      return false;
    auto others = [&](int t, int& a, int& b) {
      a = b = -1;
      for (int w : this->T[t])
        if (w != u && w != v)
          (a < 0 ? a : b) = w;
    };
    int a, b;
    others(around[0], a, b);
    if (amTetraGeometry::SignedVolume(this->X(u), this->X(v), this->X(a), this->X(b)) < 0)
      std::swap(a, b);
    tets.push_back(around[0]);
    ring.push_back(a);
    std::vector<char> used(around.size(), 0);
    used[0] = 1;
    int current = b;
    while (current != a)
    {
      bool found = false;
      for (size_t k = 1; k < around.size() && !found; ++k)
      {
        if (used[k])
          continue;
        int x, y;
        others(around[k], x, y);
        if (x == current || y == current)
        {
          used[k] = 1;
          tets.push_back(around[k]);
          ring.push_back(current);
          current = x == current ? y : x;
          found = true;
        }
      }
      if (!found)
        return false;
    }
    return tets.size() == around.size();
  }
};

/// Edge removal: replaces the tetrahedra around (u, v) by the best triangulation of their ring.
bool RemoveEdge(Mesh& m, int u, int v, int maxRing, std::vector<int>& tets, std::vector<int>& ring)
{
  if (m.FixedEdges.count(EdgeKey(u, v)) || !m.Ring(u, v, tets, ring))
    return false;
  const int n = static_cast<int>(ring.size());
  if (n > maxRing)
    return false;
  double old = std::numeric_limits<double>::infinity();
  for (int t : tets)
    old = std::min(old, m.Q[t]);
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
  const int region = m.R[tets[0]];
  std::vector<std::array<int, 2>> todo{ { 0, n - 1 } };
  std::vector<Tet> made;
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
  for (int t : tets)
    m.Kill(t);
  for (const Tet& t : made)
    m.Add(t, region);
  return true;
}

/// 2-3 flip of the face of tetrahedron t opposite its vertex i.
bool Flip23(Mesh& m, int t, int i)
{
  const Tet& x = m.T[t];
  const int d = x[i], a = x[(i + 1) % 4], b = x[(i + 2) % 4], c = x[(i + 3) % 4];
  if (m.FixedFaces.count(Sorted(a, b, c)))
    return false;
  int other = -1;
  for (int s : m.Inc[a])
    if (s != t && m.Has(s, b) && m.Has(s, c))
    {
      other = s;
      break;
    }
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
  const double old = std::min(m.Q[t], m.Q[other]);
  double q = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
    q = std::min(q, m.Quality(d, e, ring[k], ring[(k + 1) % 3]));
  if (!(q > old + 1e-12))
    return false;
  const int region = m.R[t];
  m.Kill(t);
  m.Kill(other);
  for (int k = 0; k < 3; ++k)
    m.Add({ d, e, ring[k], ring[(k + 1) % 3] }, region);
  return true;
}

/// The star of v as it is: its worst objective and the sum of the inverse objectives.
void CurrentStar(const Mesh& m, int v, double& worst, double& sum)
{
  worst = std::numeric_limits<double>::infinity();
  sum = 0;
  for (int t : m.Inc[v])
  {
    worst = std::min(worst, m.Q[t]);
    sum += 1.0 / m.Q[t];
  }
}

/// The star of v with v moved to x: its worst objective and the sum of the inverse objectives
/// (inf when a tetrahedron inverts).
void StarQuality(const Mesh& m, int v, const double* x, double& worst, double& sumQ)
{
  worst = std::numeric_limits<double>::infinity();
  sumQ = 0;
  for (int t : m.Inc[v])
  {
    const double* p[4];
    for (int k = 0; k < 4; ++k)
      p[k] = m.T[t][k] == v ? x : m.X(m.T[t][k]);
    const double q = amTetraMeshOptimizer::Objective(p[0], p[1], p[2], p[3]);
    worst = std::min(worst, q);
    if (q <= 0)
    {
      sumQ = std::numeric_limits<double>::infinity();
      return;
    }
    sumQ += 1.0 / q;
  }
}

void MoveVertex(Mesh& m, int v, const double* x)
{
  std::copy(x, x + 3, &m.P[3 * static_cast<size_t>(v)]);
  for (int t : m.Inc[v])
  {
    m.Q[t] = m.Quality(m.T[t][0], m.T[t][1], m.T[t][2], m.T[t][3]);
    m.Tried[t] = 0;
    for (int w : m.T[t])
      m.Dirty[w] = 1;
  }
}

/// Smoothing of one free vertex: the best of a few candidate positions that keeps the star's
/// worst element at least as good and lowers its mean Q.
bool Smooth(Mesh& m, int v)
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
  double bestSum = sum0 * (1 - 1e-9), bestPos[3];
  bool found = false;
  for (const auto& target : targets)
    for (double f : { 1.0, 0.5, 0.25 })
    {
      double y[3];
      for (int d = 0; d < 3; ++d)
        y[d] = x[d] + f * (target[d] - x[d]);
      double worst, sum;
      StarQuality(m, v, y, worst, sum);
      if (worst >= worst0 && sum < bestSum)
      {
        bestSum = sum;
        std::copy(y, y + 3, bestPos);
        found = true;
      }
    }
  if (found)
    MoveVertex(m, v, bestPos);
  return found;
}

/// Local search: moves v along the numerical gradient of its star's worst quality.
bool Climb(Mesh& m, int v)
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
      if (active < 0 || m.Q[t] < m.Q[active])
        active = t;
    const double worst0 = m.Q[active];
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
        f[s] = amTetraMeshOptimizer::Objective(p[0], p[1], p[2], p[3]);
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
      double worst, sum;
      StarQuality(m, v, y, worst, sum);
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
    old = std::min(old, m.Q[t]);
  const double mid[3] = { 0.5 * (m.X(u)[0] + m.X(v)[0]), 0.5 * (m.X(u)[1] + m.X(v)[1]),
    0.5 * (m.X(u)[2] + m.X(v)[2]) };
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
  Climb(m, w);
  Smooth(m, w);
  double now = std::numeric_limits<double>::infinity();
  for (int t : m.Inc[w])
    now = std::min(now, m.Q[t]);
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

double amTetraMeshOptimizer::Objective(const double* a, const double* b, const double* c, const double* d)
{
  const double volume = amTetraGeometry::SignedVolume(a, b, c, d);
  if (!(volume > 0))
    return -1.0;
  using G = amTetraGeometry;
  const Vec ab = G::Sub(b, a), ac = G::Sub(c, a), ad = G::Sub(d, a), bc = G::Sub(c, b), bd = G::Sub(d, b),
            cd = G::Sub(d, c);
  // Twice the area of the face opposite each vertex.
  const double fa = G::Norm(G::Cross(bc, bd)), fb = G::Norm(G::Cross(ac, ad)), fc = G::Norm(G::Cross(ab, ad)),
               fd = G::Norm(G::Cross(ab, ac));
  const double lab = G::Norm(ab), lac = G::Norm(ac), lad = G::Norm(ad), lbc = G::Norm(bc), lbd = G::Norm(bd),
               lcd = G::Norm(cd);
  const double longest = std::max({ lab, lac, lad, lbc, lbd, lcd });
  const double inradius = 6.0 * volume / (fa + fb + fc + fd);
  const double inverseQ = 2.0 * std::sqrt(6.0) * inradius / longest;
  // sin of the dihedral angle at edge ij = 3 V l_ij / (2 A_k A_l) (faces k, l opposite the
  // other two vertices); the regular tetrahedron's is sqrt(8)/3.
  const double minSine = 6.0 * volume *
    std::min({ lab / (fc * fd), lac / (fb * fd), lad / (fb * fc), lbc / (fa * fd), lbd / (fa * fc),
      lcd / (fa * fb) });
  return std::min(inverseQ, minSine * 3.0 / std::sqrt(8.0));
}

std::string amTetraMeshOptimizer::Report::Describe() const
{
  std::ostringstream os;
  os << "worst Q " << this->WorstBefore << " -> " << this->WorstAfter << ", mean " << this->MeanBefore << " -> "
     << this->MeanAfter << " (" << this->EdgeRemovals << " edge removals, " << this->Flips23 << " 2-3 flips, "
     << this->EdgeSplits << " edge splits, " << this->Moves << " vertex moves)";
  return os.str();
}

amTetraMeshOptimizer::Report amTetraMeshOptimizer::Optimize(std::vector<double>& points,
  std::vector<std::array<int, 4>>& tets, std::vector<int>& regions,
  const std::vector<std::array<int, 3>>& fixedFaces, const Options& options,
  const std::function<void(double)>& progress)
{
  Report report;
  Mesh m(points);
  m.Inc.resize(points.size() / 3);
  m.FixedVertex.assign(points.size() / 3, 0);
  m.Dirty.assign(points.size() / 3, 1);
  m.T.reserve(tets.size() * 2);
  for (size_t t = 0; t < tets.size(); ++t)
    m.Add(tets[t], regions[t]);
  auto statistics = [&](double& worst, double& mean) {
    worst = 0;
    double sum = 0;
    size_t n = 0;
    for (size_t t = 0; t < m.T.size(); ++t)
      if (m.Alive[t])
      {
        double q, minDihedral, maxDihedral, radiusRatio, volume;
        amMeshQuality::TetraQuality(m.X(m.T[t][0]), m.X(m.T[t][1]), m.X(m.T[t][2]), m.X(m.T[t][3]), q,
          minDihedral, maxDihedral, radiusRatio, volume);
        worst = std::max(worst, q);
        sum += q;
        ++n;
      }
    mean = n ? sum / static_cast<double>(n) : 0;
  };
  statistics(report.WorstBefore, report.MeanBefore);

  // Fixed: the given faces and the mesh's own boundary (faces of one tetrahedron only).
  for (const Tri& f : fixedFaces)
    m.FixedFaces.insert(Sorted(f[0], f[1], f[2]));
  {
    std::unordered_map<Tri, int, TriHash> count;
    count.reserve(tets.size() * 3);
    for (const Tet& t : tets)
      for (int i = 0; i < 4; ++i)
        ++count[Sorted(t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4])];
    for (const auto& kv : count)
      if (kv.second == 1)
        m.FixedFaces.insert(kv.first);
  }
  for (const Tri& f : m.FixedFaces)
    for (int k = 0; k < 3; ++k)
    {
      m.FixedVertex[f[k]] = 1;
      m.FixedEdges.insert(EdgeKey(f[k], f[(k + 1) % 3]));
    }

  const double bad = 1.0 / options.FlipQuality, poor = 1.0 / options.SearchQuality,
               split = 1.0 / options.SplitQuality;
  const int maxRing = std::min(options.MaxRing, 15);
  std::vector<int> ringTets, ring;
  for (int pass = 0; pass < options.Passes; ++pass)
  {
    long changes = 0;
    // Topology: the bad tetrahedra's edges, then faces.
    const size_t limit = m.T.size();
    for (size_t t = 0; t < limit; ++t)
    {
      if (!m.Alive[t] || m.Tried[t] || m.Q[t] >= bad)
        continue;
      bool done = false;
      static const int edges[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
      for (int e = 0; e < 6 && !done; ++e)
        done = RemoveEdge(m, m.T[t][edges[e][0]], m.T[t][edges[e][1]], maxRing, ringTets, ring);
      if (done)
      {
        ++report.EdgeRemovals;
        ++changes;
        continue;
      }
      for (int i = 0; i < 4 && !done; ++i)
        done = Flip23(m, static_cast<int>(t), i);
      if (done)
      {
        ++report.Flips23;
        ++changes;
        continue;
      }
      // The last resort for the worst elements: split a free edge (the longest first).
      if (m.Q[t] < split)
      {
        std::array<std::pair<double, int>, 6> order;
        for (int e = 0; e < 6; ++e)
        {
          const Vec d = amTetraGeometry::Sub(m.X(m.T[t][edges[e][0]]), m.X(m.T[t][edges[e][1]]));
          order[e] = { -amTetraGeometry::Dot(d, d), e };
        }
        std::sort(order.begin(), order.end());
        const Tet x = m.T[t];
        for (int k = 0; k < 6 && !done; ++k)
          done = SplitEdge(m, x[edges[order[k].second][0]], x[edges[order[k].second][1]], split, ringTets, ring);
        if (done)
        {
          ++report.EdgeSplits;
          ++changes;
          continue;
        }
      }
      m.Tried[t] = 1;
    }
    // Geometry: smoothing of every free vertex, then a local search around the bad elements.
    const size_t nv = m.Inc.size();
    for (size_t v = 0; v < nv; ++v)
    {
      if (m.FixedVertex[v] || !m.Dirty[v])
        continue;
      m.Dirty[v] = 0;
      if (Smooth(m, static_cast<int>(v)))
      {
        ++report.Moves;
        ++changes;
      }
    }
    std::vector<char> climb(nv, 0);
    for (size_t t = 0; t < m.T.size(); ++t)
      if (m.Alive[t] && m.Q[t] < poor)
        for (int w : m.T[t])
          climb[w] = !m.FixedVertex[w];
    for (size_t v = 0; v < nv; ++v)
      if (climb[v] && Climb(m, static_cast<int>(v)))
      {
        ++report.Moves;
        ++changes;
      }
    if (progress)
      progress(static_cast<double>(pass + 1) / options.Passes);
    if (changes == 0)
      break;
  }

  tets.clear();
  regions.clear();
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
    {
      tets.push_back(m.T[t]);
      regions.push_back(m.R[t]);
    }
  statistics(report.WorstAfter, report.MeanAfter);
  return report;
}

bool amTetraMeshOptimizer::ImproveGrid(vtkUnstructuredGrid* grid, vtkPolyData* surface, const Options& options,
  Report& report, std::string& why, const std::function<void(double)>& progress)
{
  vtkPoints* gridPoints = grid->GetPoints();
  vtkDataArray* regionArray = grid->GetCellData()->GetArray("Region");
  vtkDataArray* labels = surface->GetCellData()->GetArray("Labels");
  const vtkIdType np = grid->GetNumberOfPoints(), ne = grid->GetNumberOfCells(), ns = surface->GetNumberOfCells();
  if (!gridPoints || !regionArray || !labels || labels->GetNumberOfComponents() != 2 ||
    surface->GetPoints() != gridPoints)
  {
    why = "the grid needs a Region array and the surface a 2-component Labels array on the grid's points";
    return false;
  }
  std::vector<double> points(3 * static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
    gridPoints->GetPoint(v, &points[3 * v]);
  std::vector<Tet> tets(static_cast<size_t>(ne));
  std::vector<int> regions(static_cast<size_t>(ne));
  for (vtkIdType c = 0; c < ne; ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    if (n != 4)
    {
      why = "cell " + std::to_string(c) + " is not a tetrahedron";
      return false;
    }
    for (int k = 0; k < 4; ++k)
      tets[c][k] = static_cast<int>(ids[k]);
    if (amTetraGeometry::SignedVolume(&points[3 * ids[0]], &points[3 * ids[1]], &points[3 * ids[2]],
          &points[3 * ids[3]]) < 0)
      std::swap(tets[c][0], tets[c][1]);
    regions[c] = static_cast<int>(regionArray->GetComponent(c, 0));
  }
  std::vector<Tri> fixed(static_cast<size_t>(ns));
  for (vtkIdType s = 0; s < ns; ++s)
  {
    vtkIdType n;
    const vtkIdType* ids;
    surface->GetCellPoints(s, n, ids);
    if (n != 3)
    {
      why = "surface cell " + std::to_string(s) + " is not a triangle";
      return false;
    }
    fixed[s] = { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) };
  }
  report = Optimize(points, tets, regions, fixed, options, progress);

  // Back into the grid: moved and new points (-1 in every point array: they lie inside, on no
  // surface), new cells, their regions.
  for (vtkIdType v = 0; v < np; ++v)
    gridPoints->SetPoint(v, &points[3 * v]);
  const vtkIdType nAll = static_cast<vtkIdType>(points.size() / 3);
  for (vtkIdType v = np; v < nAll; ++v)
    gridPoints->InsertNextPoint(&points[3 * v]);
  vtkPointData* pd = grid->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    if (vtkDataArray* array = pd->GetArray(a))
      for (vtkIdType v = np; v < nAll; ++v)
        for (int c = 0; c < array->GetNumberOfComponents(); ++c)
          array->InsertComponent(v, c, -1.0);
  gridPoints->Modified();
  const vtkIdType nt = static_cast<vtkIdType>(tets.size());
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(nt + 1);
  connectivity->SetNumberOfTuples(4 * nt);
  vtkNew<vtkIntArray> region;
  region->SetName(regionArray->GetName());
  region->SetNumberOfTuples(nt);
  for (vtkIdType c = 0; c < nt; ++c)
  {
    offsets->SetValue(c, 4 * c);
    for (int k = 0; k < 4; ++k)
      connectivity->SetValue(4 * c + k, tets[c][k]);
    region->SetValue(c, regions[c]);
  }
  offsets->SetValue(nt, 4 * nt);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(VTK_TETRA, cells);
  grid->GetCellData()->Initialize(); // per-cell data of the old cells no longer applies
  grid->GetCellData()->AddArray(region);
  grid->GetCellData()->SetActiveScalars(region->GetName());

  // The surface's "Tetra": the tetrahedron on the Labels[0] and on the Labels[1] side of each
  // triangle (the normal points into the Labels[1] side).
  vtkNew<vtkIntArray> adjacent;
  adjacent->SetName("Tetra");
  adjacent->SetNumberOfComponents(2);
  adjacent->SetNumberOfTuples(ns);
  adjacent->Fill(-1);
  std::unordered_map<Tri, int, TriHash> faceOf;
  faceOf.reserve(static_cast<size_t>(ns) * 2);
  for (vtkIdType s = 0; s < ns; ++s)
    faceOf[Sorted(fixed[s][0], fixed[s][1], fixed[s][2])] = static_cast<int>(s);
  for (vtkIdType c = 0; c < nt; ++c)
    for (int i = 0; i < 4; ++i)
    {
      const Tet& t = tets[c];
      const auto it = faceOf.find(Sorted(t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4]));
      if (it == faceOf.end())
        continue;
      const Tri& f = fixed[it->second];
      const int side = amTetraGeometry::SignedVolume(&points[3 * static_cast<size_t>(f[0])],
                         &points[3 * static_cast<size_t>(f[1])], &points[3 * static_cast<size_t>(f[2])],
                         &points[3 * static_cast<size_t>(t[i])]) > 0
        ? 1
        : 0;
      adjacent->SetComponent(it->second, side, static_cast<double>(c));
    }
  surface->GetCellData()->RemoveArray("Tetra");
  surface->GetCellData()->AddArray(adjacent);
  grid->Modified();
  surface->Modified();
  return true;
}
