#include "amMetricRemeshing.h"

#include "amProvenance.h"
#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amThreading.h"
#include "amTriangleLocator.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_map>

vtkStandardNewMacro(amMetricRemeshing);

namespace
{
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// A coarse grid over a set of points, its cells flagged where they come within Reach of a
/// triangle of a set: a point whose cell is not flagged is farther than Reach from all of them.
class NearCells
{
public:
  void Build(const std::vector<Vec3>& points, double reach, const std::vector<std::array<double, 3>>& pts,
    const std::vector<std::array<vtkIdType, 3>>& tris)
  {
    this->Reach = reach;
    this->Lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -this->Lo;
    for (const Vec3& x : points)
    {
      this->Lo = this->Lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    if (points.empty())
      return;
    // Cells at least twice the reach, at most 64 along the longest side (a few hundred thousand
    // bytes per interface, cleared at every measure).
    this->G = std::max({ 2.0 * reach, (hi - this->Lo).maxCoeff() / 64.0, 1e-9 });
    for (int d = 0; d < 3; ++d)
      this->N[d] = static_cast<int>((hi[d] - this->Lo[d]) / this->G) + 1;
    this->Cell.assign(static_cast<size_t>(this->N[0]) * this->N[1] * this->N[2], 0);
    for (const auto& t : tris)
    {
      int lo[3], up[3];
      for (int d = 0; d < 3; ++d)
      {
        const double a = std::min({ pts[t[0]][d], pts[t[1]][d], pts[t[2]][d] }) - reach,
                     b = std::max({ pts[t[0]][d], pts[t[1]][d], pts[t[2]][d] }) + reach;
        lo[d] = std::max(0, static_cast<int>(std::floor((a - this->Lo[d]) / this->G)));
        up[d] = std::min(this->N[d] - 1, static_cast<int>(std::floor((b - this->Lo[d]) / this->G)));
      }
      for (int k = lo[2]; k <= up[2]; ++k)
        for (int j = lo[1]; j <= up[1]; ++j)
          for (int i = lo[0]; i <= up[0]; ++i)
            this->Cell[(static_cast<size_t>(k) * this->N[1] + j) * this->N[0] + i] = 1;
    }
  }
  /// Whether a point of the set, at squared distance d2 from its nearest triangle, may have one
  /// of the set's triangles nearer than that.
  bool MayComeNearer(const Vec3& x, double d2) const
  {
    if (d2 > this->Reach * this->Reach || this->Cell.empty())
      return true;
    int c[3];
    for (int d = 0; d < 3; ++d)
      c[d] = std::min(this->N[d] - 1, std::max(0, static_cast<int>((x[d] - this->Lo[d]) / this->G)));
    return this->Cell[(static_cast<size_t>(c[2]) * this->N[1] + c[1]) * this->N[0] + c[0]] != 0;
  }

private:
  double Reach = 0, G = 1;
  Vec3 Lo = Vec3::Zero();
  int N[3] = { 0, 0, 0 };
  std::vector<char> Cell;
};

struct Tri
{
  int V[3];
  int Sheet;
  int Labels[2];
  bool Alive;
};

/// Smallest angle (radians) an insertion or edge split may create: a refused one refines
/// the triangle instead (longest-edge split), which makes room for the next attempt.
const double MinimumNewAngle = 2.0 * M_PI / 180.0;

/// Triangles with an angle under this are removed after the insertions where the checks allow.
const double SmallAngle = 10.0 * M_PI / 180.0;

/// Edges shorter than this in the metric are collapsed where no edge longer than LongEdge results
/// (1.4 instead of 4/3 gave 10.3x fewer triangles instead of 9.7x on the 1 mm phantom, but the
/// main job's organs then meshed into tetrahedra of mean quality 1.4001, just above its 1.4 bar).
const double ShortEdge = 0.8;
const double LongEdge = 4.0 / 3.0;

/// Which worker the calling thread is (collapse passes run one per part of the surface, see
/// CollapsePass; everything else runs as worker 0), and the part it may change (-1: any).
thread_local int CurrentWorker = 0;
thread_local int CurrentZone = -1;

double MinAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  // The largest cosine, then one arc cosine (it is monotonic).
  const Vec3 p[3] = { a, b, c };
  double largest = -1.0;
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
    const double nu = u.norm(), nv = v.norm();
    if (nu == 0 || nv == 0)
      return 0;
    largest = std::max(largest, u.dot(v) / (nu * nv));
  }
  return std::acos(std::max(-1.0, std::min(1.0, largest)));
}

class Remesher
{
public:
  std::vector<Vec3> P;
  std::vector<Mat3> M;
  std::vector<unsigned char> Kind;
  std::vector<char> VAlive;
  std::vector<Tri> T;
  std::vector<std::vector<int>> VT;
  std::vector<amTriangleLocator> Ref; // per sheet: the input surface
  std::vector<std::vector<Vec3>> RefSamples; // per sheet: input vertices, edge midpoints, centroids
  std::vector<Vec3> RefPoints;                // the input vertices
  // Input vertices each vertex stands for, with the interface they must stay near (-1: every
  // interface around the vertex, for junction-curve points).
  // Each entry also keeps a triangle of the vertex's star found within Eps of it (-1: none yet):
  // while that triangle is still in the vertex's star and untouched (every operation that
  // changes a triangle's vertices or their positions passes it as removed), the entry needs no
  // search.
  struct ClusterEntry
  {
    int Point;
    int Sheet;
    int Hint;
  };
  std::vector<std::vector<ClusterEntry>> Cluster;
  struct NearTriangle
  {
    int Id;
    std::array<int, 3> V;
    Vec3 X[3], Lo, Hi;
  };
  /// What one worker's operations use besides the mesh (on a cache line of its own: the two
  /// workers' counters must not share one).
  struct alignas(64) Worker
  {
    // Hints found by the last ClustersStayNear (owner, entry, triangle), kept if the operation is.
    std::vector<std::array<int, 3>> PendingHints;
    std::vector<NearTriangle> Near; // the live triangles near the last operation's
    std::vector<int> Stamp;         // per triangle: the last crossing check that saw it
    int StampValue = 0;
    int LastHit = -1; // the live triangle the last refused operation would have crossed
    long long Collapses = 0, Moves = 0, Flips = 0;
    std::vector<int> Removed; // per component (see FindComponents): vertices this worker removed
    // Collapse's work vectors, kept (a collapse allocated a dozen vectors; none outlives the
    // call, and nothing called from Collapse collapses).
    struct
    {
      std::vector<int> Edge, Na, Nb, Common, Apex, Changed, Removed, Sheets, Affected;
      std::vector<std::array<int, 3>> Ids;
      std::vector<std::array<Vec3, 3>> Pos;
    } C;
  };
  mutable std::array<Worker, 2> Workers;
  Worker& W() const { return this->Workers[CurrentWorker]; }
  void KeepHints()
  {
    auto& pending = this->W().PendingHints;
    for (const auto& h : pending)
      this->Cluster[h[0]][h[1]].Hint = h[2];
    pending.clear();
  }
  // Per input vertex on a junction curve or corner: the interfaces around it (sorted) and its
  // neighbours along the curves (with the edge lengths). Every curve vertex of the result sits on
  // an input curve vertex, its anchor (-1 for surface vertices): its triangles may only belong to
  // the anchor's interfaces, and a junction edge is split at the input curve vertex halfway
  // along the input curve between its two anchors, so the curves of the result visit the
  // input's curve vertices in their order (splitting at the curve vertex nearest the edge's
  // midpoint could pick one from a neighbouring stretch of the curve and fold it back).
  std::vector<std::vector<int>> InputSheets;
  std::vector<std::vector<std::pair<int, double>>> CurveNeighbours;
  std::vector<int> Anchor;
  bool Allowed(int v, int sheet) const
  {
    if (this->Kind[v] == amSurfaceMesh::Surface || this->Anchor[v] < 0)
      return true;
    const auto& sheets = this->InputSheets[this->Anchor[v]];
    return std::binary_search(sheets.begin(), sheets.end(), sheet);
  }
  /// The input curve vertex halfway (by length) along the shortest input curve path from a to b
  /// no longer than maxLength, not a or b themselves (-1: no such path, or no vertex between).
  int CurveMiddle(int a, int b, double maxLength) const
  {
    std::unordered_map<int, std::pair<double, int>> dist; // vertex: distance from a, previous
    std::vector<std::pair<double, int>> heap{ { 0.0, a } };
    dist[a] = { 0.0, -1 };
    bool found = false;
    while (!heap.empty())
    {
      std::pop_heap(heap.begin(), heap.end(), std::greater<>());
      const auto [d, v] = heap.back();
      heap.pop_back();
      if (d > dist[v].first)
        continue;
      if (v == b)
      {
        found = true;
        break;
      }
      for (const auto& [w, l] : this->CurveNeighbours[v])
      {
        const double dw = d + l;
        if (dw > maxLength)
          continue;
        auto it = dist.find(w);
        if (it == dist.end() || dw < it->second.first)
        {
          dist[w] = { dw, v };
          heap.push_back({ dw, w });
          std::push_heap(heap.begin(), heap.end(), std::greater<>());
        }
      }
    }
    if (!found)
      return -1;
    const double half = 0.5 * dist[b].first;
    int best = -1;
    double bestGap = std::numeric_limits<double>::infinity();
    for (int v = dist[b].second; v != a && v >= 0; v = dist[v].second)
      if (std::abs(dist[v].first - half) < bestGap)
      {
        bestGap = std::abs(dist[v].first - half);
        best = v;
      }
    return best;
  }
  double Eps = 0.2;

  // Bins of the live triangles (entries may be stale: a query checks the actual bounding box), so
  // that every local operation can refuse to make a triangle cross another one. The bins are
  // kept in three maps: bins before the split plane (index along SplitAxis below SplitIndex),
  // after it, and on it, so that two workers can each change the triangles of one side.
  double BinSize = 1.0;
  std::array<std::unordered_map<long long, std::vector<int>>, 3> Bins;
  int SplitAxis = 0;
  long long SplitIndex = 0;
  int ZoneOf(long long index) const
  {
    return index < this->SplitIndex ? 0 : (index > this->SplitIndex ? 1 : 2);
  }
  /// The zone of the bins holding point x.
  int ZoneAt(const Vec3& x) const
  {
    return this->ZoneOf(static_cast<long long>(std::floor(x[this->SplitAxis] / this->BinSize)));
  }
  /// Whether the box lies in zone z's bins.
  bool BoxInZone(const Vec3& lo, const Vec3& hi, int z) const
  {
    return this->ZoneAt(lo) == z && this->ZoneAt(hi) == z;
  }

  static long long BinKey(long long i, long long j, long long k)
  {
    return ((i + (1 << 20)) << 42) | ((j + (1 << 20)) << 21) | (k + (1 << 20));
  }
  void Box(const Vec3* p, Vec3& lo, Vec3& hi) const
  {
    lo = p[0].cwiseMin(p[1]).cwiseMin(p[2]);
    hi = p[0].cwiseMax(p[1]).cwiseMax(p[2]);
  }
  template <typename F>
  void ForBins(const Vec3& lo, const Vec3& hi, F f)
  {
    long long l[3], h[3];
    for (int d = 0; d < 3; ++d)
    {
      l[d] = static_cast<long long>(std::floor(lo[d] / this->BinSize));
      h[d] = static_cast<long long>(std::floor(hi[d] / this->BinSize));
    }
    for (long long i = l[0]; i <= h[0]; ++i)
      for (long long j = l[1]; j <= h[1]; ++j)
        for (long long k = l[2]; k <= h[2]; ++k)
        {
          const long long index[3] = { i, j, k };
          f(BinKey(i, j, k), this->ZoneOf(index[this->SplitAxis]));
        }
  }
  /// Per triangle slot: the range of bins (index box lo 0..2, hi 3..5) it is in (lo > hi: none).
  /// The bins stay exact: every change of a triangle moves it to the bins of its new box, and a
  /// triangle that dies leaves them (stale entries had to be purged by rebuilding the bins before
  /// each pass, so that no entry names a triangle the other worker changes).
  std::vector<std::array<int, 6>> BinnedIn;
  /// Per triangle slot: its bounding box when it was last binned (lo 0..2, hi 3..5), rounded
  /// outwards to floats: the crossing check's first test reads this one small record; the
  /// triangle and its three corners are read only for the triangles that pass it.
  std::vector<std::array<float, 6>> BinnedBox;
  std::array<int, 6> BinRange(int t, std::array<float, 6>* box = nullptr) const
  {
    Vec3 p[3], lo, hi;
    for (int k = 0; k < 3; ++k)
      p[k] = this->P[this->T[t].V[k]];
    this->Box(p, lo, hi);
    if (box)
      for (int d = 0; d < 3; ++d)
      {
        float l = static_cast<float>(lo[d]), h = static_cast<float>(hi[d]);
        (*box)[d] = l > lo[d] ? std::nextafter(l, -std::numeric_limits<float>::infinity()) : l;
        (*box)[d + 3] = h < hi[d] ? std::nextafter(h, std::numeric_limits<float>::infinity()) : h;
      }
    std::array<int, 6> r;
    for (int d = 0; d < 3; ++d)
    {
      r[d] = static_cast<int>(std::floor(lo[d] / this->BinSize));
      r[d + 3] = static_cast<int>(std::floor(hi[d] / this->BinSize));
    }
    return r;
  }
  /// Calls f(key, zone) for the bins of range r outside range 'except' (null: none).
  template <typename F>
  void ForRange(const std::array<int, 6>& r, const std::array<int, 6>* except, F f) const
  {
    for (long long i = r[0]; i <= r[3]; ++i)
      for (long long j = r[1]; j <= r[4]; ++j)
        for (long long k = r[2]; k <= r[5]; ++k)
        {
          if (except && i >= (*except)[0] && i <= (*except)[3] && j >= (*except)[1] && j <= (*except)[4] &&
            k >= (*except)[2] && k <= (*except)[5])
            continue;
          const long long index[3] = { i, j, k };
          f(BinKey(i, j, k), this->ZoneOf(index[this->SplitAxis]));
        }
  }
  void RemoveFromBins(int t, const std::array<int, 6>& r, const std::array<int, 6>* except)
  {
    this->ForRange(r, except, [&](long long key, int zone) {
      auto it = this->Bins[zone].find(key);
      if (it == this->Bins[zone].end())
        return;
      auto& list = it->second;
      auto at = std::find(list.begin(), list.end(), t);
      if (at != list.end())
      {
        *at = list.back();
        list.pop_back();
      }
    });
  }
  /// Live triangle t (new, or changed since it was last binned) into the bins its box touches,
  /// and out of those it no longer touches.
  void BinTriangle(int t)
  {
    if (this->BinnedIn.size() <= static_cast<size_t>(t))
    {
      this->BinnedIn.resize(this->T.size(), { 0, 0, 0, -1, -1, -1 });
      this->BinnedBox.resize(this->T.size(), { 1, 1, 1, 0, 0, 0 });
    }
    const std::array<int, 6> r = this->BinRange(t, &this->BinnedBox[t]), old = this->BinnedIn[t];
    const bool had = old[0] <= old[3];
    if (had && r == old)
      return;
    if (had)
      this->RemoveFromBins(t, old, &r);
    this->ForRange(r, had ? &old : nullptr, [&](long long key, int zone) { this->Bins[zone][key].push_back(t); });
    this->BinnedIn[t] = r;
  }
  /// Triangle t out of every bin (it dies).
  void Unbin(int t)
  {
    if (static_cast<size_t>(t) >= this->BinnedIn.size() || this->BinnedIn[t][0] > this->BinnedIn[t][3])
      return;
    this->RemoveFromBins(t, this->BinnedIn[t], nullptr);
    this->BinnedIn[t] = { 0, 0, 0, -1, -1, -1 };
    this->BinnedBox[t] = { 1, 1, 1, 0, 0, 0 };
  }
  /// The triangles ts binned again after a change.
  void Rebin(const std::vector<int>& ts)
  {
    for (int t : ts)
      this->BinTriangle(t);
  }
  /// RebuildBins where the bins no longer fit the triangles: their size (twice the mean edge
  /// length) off by more than a quarter. (The bins stay exact without it, and the split plane
  /// stays where it was.)
  void RebuildBinsIfStale()
  {
    const double size = this->FittingBinSize();
    if (size > 1.25 * this->BinSize || size < 0.8 * this->BinSize || this->BinnedIn.size() != this->T.size())
      this->RebuildBins();
  }
  /// The Morton code of the cube of side 'cell' holding x (21 bits per axis).
  static unsigned long long MortonCode(const Vec3& x, double cell)
  {
    auto spread = [](unsigned long long v) {
      v &= 0x1fffff;
      v = (v | v << 32) & 0x1f00000000ffffULL;
      v = (v | v << 16) & 0x1f0000ff0000ffULL;
      v = (v | v << 8) & 0x100f00f00f00f00fULL;
      v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
      v = (v | v << 2) & 0x1249249249249249ULL;
      return v;
    };
    unsigned long long code = 0;
    for (int d = 0; d < 3; ++d)
      code |= spread(static_cast<unsigned long long>(static_cast<long long>(std::floor(x[d] / cell)) + (1 << 20))) << d;
    return code;
  }
  /// The bin size that fits the triangles now: twice their mean edge length.
  double FittingBinSize() const
  {
    // Summed in blocks of a fixed size on the threads, then the blocks in order: the same sum
    // whatever the number of threads (every pass asks, and most slots are dead ones).
    const size_t block = 1 << 14, nBlocks = (this->T.size() + block - 1) / block;
    std::vector<double> sums(nBlocks, 0.0);
    std::vector<long long> counts(nBlocks, 0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(nBlocks), [&](vtkIdType b0, vtkIdType b1) {
      for (vtkIdType b = b0; b < b1; ++b)
        for (size_t i = b * block; i < std::min(this->T.size(), static_cast<size_t>(b + 1) * block); ++i)
          if (this->T[i].Alive)
            for (int k = 0; k < 3; ++k, ++counts[b])
              sums[b] += (this->P[this->T[i].V[(k + 1) % 3]] - this->P[this->T[i].V[k]]).norm();
    });
    double sum = 0;
    long long n = 0;
    for (size_t b = 0; b < nBlocks; ++b)
    {
      sum += sums[b];
      n += counts[b];
    }
    return n ? std::max(2.0 * sum / n, 1e-6) : 1.0;
  }
  void RebuildBins()
  {
    this->BinSize = this->FittingBinSize();
    // The split: across the longest side of the bounding box, at the median vertex.
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    std::vector<double> along;
    for (size_t v = 0; v < this->P.size(); ++v)
      if (this->VAlive[v] && !this->VT[v].empty())
      {
        lo = lo.cwiseMin(this->P[v]);
        hi = hi.cwiseMax(this->P[v]);
      }
    if (lo[0] <= hi[0])
    {
      (hi - lo).maxCoeff(&this->SplitAxis);
      for (size_t v = 0; v < this->P.size(); ++v)
        if (this->VAlive[v] && !this->VT[v].empty())
          along.push_back(this->P[v][this->SplitAxis]);
      std::nth_element(along.begin(), along.begin() + along.size() / 2, along.end());
      this->SplitIndex = static_cast<long long>(std::floor(along[along.size() / 2] / this->BinSize));
    }
    // Emptied and filled on two threads, one for the bins before the split plane and on it, one
    // for those after it (each bin lists its triangles in their order, as BinTriangle would one
    // by one).
    this->BinnedIn.assign(this->T.size(), { 0, 0, 0, -1, -1, -1 });
    this->BinnedBox.assign(this->T.size(), { 1, 1, 1, 0, 0, 0 });
    vtkSMPTools::For(0, 2, 1, [&](vtkIdType z0, vtkIdType z1) {
      for (vtkIdType z = z0; z < z1; ++z)
      {
        for (int zone : { 0, 1, 2 })
          if ((zone == 1) == (z == 1))
            this->Bins[zone].clear();
        for (size_t t = 0; t < this->T.size(); ++t)
          if (this->T[t].Alive)
          {
            const std::array<int, 6> r = this->BinRange(static_cast<int>(t), z == 0 ? &this->BinnedBox[t] : nullptr);
            if (z == 0)
              this->BinnedIn[t] = r;
            this->ForRange(r, nullptr, [&](long long key, int zone) {
              if ((zone == 1) == (z == 1))
                this->Bins[zone][key].push_back(static_cast<int>(t));
            });
          }
      }
    });
  }
  /// Whether the vertices of q not shared with p lie strictly on one side of p's plane.
  static bool Separated(const Vec3* p, const int* ip, const Vec3* q, const int* iq)
  {
    // The margin from sums of absolute values (no square roots): each is at least the length.
    const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
    const double nl = n.lpNorm<1>();
    const double scale = nl * ((p[1] - p[0]).lpNorm<1>() + (p[2] - p[0]).lpNorm<1>());
    int side = 0;
    for (int j = 0; j < 3; ++j)
    {
      if (iq[j] == ip[0] || iq[j] == ip[1] || iq[j] == ip[2])
        continue;
      const double d = n.dot(q[j] - p[0]);
      const double margin = 1e-9 * (scale + nl * (q[j] - p[0]).lpNorm<1>());
      const int s = d > margin ? 1 : (d < -margin ? -1 : 0);
      if (s == 0 || (side != 0 && s != side))
        return false;
      side = s;
    }
    return side != 0;
  }
  /// Would the new triangles (vertex ids and positions), replacing the triangles 'removed', cross
  /// any live triangle or each other (CGAL exact test; also two triangles folded flat on an edge)?
  bool Crosses(const std::vector<std::array<int, 3>>& ids, const std::vector<std::array<Vec3, 3>>& pos,
    const std::vector<int>& removed)
  {
    Worker& worker = this->W();
    if (worker.Stamp.size() < this->T.size())
      worker.Stamp.resize(this->T.size() * 2, 0);
    auto pairCrosses = [](const std::array<int, 3>& ia, const std::array<Vec3, 3>& pa,
                         const std::array<int, 3>& ib, const Vec3* pb) {
      const double* a[3] = { pa[0].data(), pa[1].data(), pa[2].data() };
      const double* b[3] = { pb[0].data(), pb[1].data(), pb[2].data() };
      const vtkIdType va[3] = { ia[0], ia[1], ia[2] }, vb[3] = { ib[0], ib[1], ib[2] };
      // Two triangles on one edge at a dihedral angle under ~5 degrees: a fold.
      int shared = 0, oa = -1, ob = -1;
      for (int i = 0; i < 3; ++i)
      {
        bool found = false;
        for (int j = 0; j < 3; ++j)
          found = found || ia[i] == ib[j];
        shared += found;
        if (!found)
          oa = i;
      }
      for (int j = 0; j < 3; ++j)
        if (ib[j] != ia[0] && ib[j] != ia[1] && ib[j] != ia[2])
          ob = j;
      if (shared == 2)
      {
        const Vec3& e0 = pa[(oa + 1) % 3];
        const Vec3 e = (pa[(oa + 2) % 3] - e0).normalized();
        Vec3 u = pa[oa] - e0, w = pb[ob] - e0;
        u -= u.dot(e) * e;
        w -= w.dot(e) * e;
        if (u.norm() > 0 && w.norm() > 0)
          // Otherwise the triangles lie in two distinct half-planes bounded by the line of the
          // shared edge, which meet only on that line: they meet only on the shared edge.
          return u.normalized().dot(w.normalized()) > 0.99985;
      }
      // Most pairs are neighbours well apart: one triangle's other vertices all strictly on one
      // side of the other's plane (by a margin far above rounding) cannot cross it.
      if (shared < 2 && (Separated(pa.data(), ia.data(), pb, ib.data()) || Separated(pb, ib.data(), pa.data(), ia.data())))
        return false;
      return amSelfIntersection::Cross(a, va, b, vb);
    };
    Vec3 lo = pos[0][0], hi = pos[0][0];
    for (size_t n = 0; n < ids.size(); ++n)
    {
      // A new triangle with (nearly) no area is refused like a crossing: TetGen rejects those.
      const Vec3 e0 = pos[n][1] - pos[n][0], e1 = pos[n][2] - pos[n][0], e2 = pos[n][2] - pos[n][1];
      const double longest2 = std::max({ e0.squaredNorm(), e1.squaredNorm(), e2.squaredNorm() });
      if (e0.cross(e1).norm() <= 1e-6 * longest2)
      {
        worker.LastHit = -1;
        return true;
      }
      for (size_t m = n + 1; m < ids.size(); ++m)
        if (pairCrosses(ids[n], pos[n], ids[m], pos[m].data()))
        {
          worker.LastHit = -1;
          return true;
        }
      for (const Vec3& x : pos[n])
      {
        lo = lo.cwiseMin(x);
        hi = hi.cwiseMax(x);
      }
    }
    // The live triangles near the new ones, each once (the removed ones are stamped first), then
    // every pair whose boxes overlap tested exactly.
    const int stamp = ++worker.StampValue;
    for (int t : removed)
      worker.Stamp[t] = stamp;
    auto& near = worker.Near;
    near.clear();
    this->ForBins(lo, hi, [&](long long key, int zone) {
      auto it = this->Bins[zone].find(key);
      if (it == this->Bins[zone].end())
        return;
      for (int t : it->second)
      {
        const std::array<float, 6>& b = this->BinnedBox[t];
        if (b[0] > hi[0] || b[1] > hi[1] || b[2] > hi[2] || b[3] < lo[0] || b[4] < lo[1] || b[5] < lo[2] ||
          worker.Stamp[t] == stamp)
          continue;
        worker.Stamp[t] = stamp;
        if (!this->T[t].Alive)
          continue;
        NearTriangle c;
        c.Id = t;
        for (int k = 0; k < 3; ++k)
        {
          c.V[k] = this->T[t].V[k];
          c.X[k] = this->P[c.V[k]];
        }
        this->Box(c.X, c.Lo, c.Hi);
        if ((c.Lo.array() <= hi.array()).all() && (c.Hi.array() >= lo.array()).all())
          near.push_back(c);
      }
    });
    for (size_t n = 0; n < ids.size(); ++n)
    {
      Vec3 nlo, nhi;
      this->Box(pos[n].data(), nlo, nhi);
      for (const NearTriangle& c : near)
        if ((c.Lo.array() <= nhi.array()).all() && (c.Hi.array() >= nlo.array()).all() &&
          pairCrosses(ids[n], pos[n], c.V, c.X))
        {
          worker.LastHit = c.Id;
          return true;
        }
    }
    return false;
  }

  /// Metric length of the edge from x (metric mx) to vertex b.
  double Length(const Vec3& x, const Mat3& mx, int b) const
  {
    const Vec3 e = this->P[b] - x;
    return 0.5 * (std::sqrt(std::max(0.0, e.dot(mx * e))) + std::sqrt(std::max(0.0, e.dot(this->M[b] * e))));
  }
  double Length(int a, int b) const { return this->Length(this->P[a], this->M[a], b); }
  bool Near(int sheet, const Vec3& x, const Vec3& normal) const
  {
    // The input triangle the last query (on this thread) found: queries come in runs at nearby
    // points, and most end there.
    thread_local std::pair<int, vtkIdType> hint(-1, -1);
    if (hint.first != sheet)
      hint = { sheet, -1 };
    return this->Ref[sheet].WithinDistance(x.data(), this->Eps * this->Eps, normal.data(), &hint.second);
  }
  /// Edge midpoints, quarter points and centroid of a (new) triangle lie within Eps of its
  /// interface, of the part of it facing the way the triangle faces (a triangle across a thin
  /// part, nearer the other side's input, left far samples that no insertion could reach).
  bool TriangleNear(int sheet, const Vec3& a, const Vec3& b, const Vec3& c) const
  {
    const Vec3 n = (b - a).cross(c - a);
    if (!(this->Near(sheet, (a + b + c) / 3.0, n) && this->Near(sheet, 0.5 * (a + b), n) &&
          this->Near(sheet, 0.5 * (b + c), n) && this->Near(sheet, 0.5 * (c + a), n)))
      return false;
    // The quarter points too: with midpoints alone, edges bent over a crease of the input passed
    // and left far samples that no insertion could reach (1 mm phantom: 0.234 mm for 0.2).
    for (double f : { 0.25, 0.75 })
      if (!this->Near(sheet, a + f * (b - a), n) || !this->Near(sheet, b + f * (c - b), n) ||
        !this->Near(sheet, c + f * (a - c), n))
        return false;
    return true;
  }
  /// TriangleNear for the new triangles (ids, positions, sheets) around one vertex, 'centre' (a
  /// collapse's b, a moved vertex). Their edges away from the centre are edges of the mesh
  /// already, checked when they were made, and so are the spokes to the vertices 'kept' (sorted:
  /// those whose edge to the centre is there already, unmoved). Each other spoke is sampled once
  /// per interface, and each centroid. (Sampling every new triangle whole took a third of a
  /// collapse's time, three times over for the same points.)
  bool StarNear(const std::vector<std::array<int, 3>>& ids, const std::vector<std::array<Vec3, 3>>& pos,
    const std::vector<int>& sheets, int centre, const std::vector<int>& kept) const
  {
    thread_local std::vector<std::pair<int, int>> sampled; // spokes done: far end, sheet
    sampled.clear();
    for (size_t n = 0; n < ids.size(); ++n)
    {
      const auto& p = pos[n];
      const int k = ids[n][0] == centre ? 0 : (ids[n][1] == centre ? 1 : (ids[n][2] == centre ? 2 : -1));
      if (k < 0)
      {
        if (!this->TriangleNear(sheets[n], p[0], p[1], p[2]))
          return false;
        continue;
      }
      const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
      if (!this->Near(sheets[n], (p[0] + p[1] + p[2]) / 3.0, normal))
        return false;
      for (int e : { 1, 2 })
      {
        const int o = ids[n][(k + e) % 3];
        const std::pair<int, int> spoke(o, sheets[n]);
        if (std::binary_search(kept.begin(), kept.end(), o) ||
          std::find(sampled.begin(), sampled.end(), spoke) != sampled.end())
          continue;
        sampled.push_back(spoke);
        const Vec3 &c = p[k], &q = p[(k + e) % 3];
        for (double f : { 0.5, 0.25, 0.75 })
          if (!this->Near(sheets[n], c + f * (q - c), normal))
            return false;
      }
    }
    return true;
  }
  void Neighbours(int v, std::vector<int>& out) const
  {
    out.clear();
    for (int t : this->VT[v])
      for (int k = 0; k < 3; ++k)
        if (this->T[t].V[k] != v)
          out.push_back(this->T[t].V[k]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  /// Whether every input vertex that an affected vertex stands for stays within Eps of that
  /// vertex's triangles of its interface (a junction-curve point: of every interface around the
  /// vertex) once the triangles 'removed' are replaced by the new ones (ids, positions, sheets).
  /// 'from' (or -1) is a vertex disappearing into 'into': its points are checked with into's.
  /// Every operation keeps this, so no patch of the input can drift away from the result.
  /// 'newIds' are the ids the new triangles will have.
  bool ClustersStayNear(const std::vector<int>& removed, const std::vector<std::array<int, 3>>& ids,
    const std::vector<std::array<Vec3, 3>>& pos, const std::vector<int>& sheets, const std::vector<int>& newIds,
    const std::vector<int>& affected, int from = -1, int into = -1) const
  {
    const double eps2 = this->Eps * this->Eps;
    struct StarTriangle
    {
      int Sheet, Id;
      std::array<Vec3, 3> X;
    };
    thread_local std::vector<StarTriangle> star;
    thread_local std::vector<int> starSheets;
    auto& pending = this->W().PendingHints;
    pending.clear();
    for (int w : affected)
    {
      // The star of w afterwards, gathered on the first search (most entries keep their hint).
      bool gathered = false;
      auto gather = [&]() {
        if (gathered)
          return;
        gathered = true;
        star.clear();
        for (int t : this->VT[w])
          if (std::find(removed.begin(), removed.end(), t) == removed.end())
            star.push_back({ this->T[t].Sheet, t,
              { this->P[this->T[t].V[0]], this->P[this->T[t].V[1]], this->P[this->T[t].V[2]] } });
        for (size_t n = 0; n < ids.size(); ++n)
          if (ids[n][0] == w || ids[n][1] == w || ids[n][2] == w)
            star.push_back({ sheets[n], newIds[n], pos[n] });
        starSheets.clear();
        for (const auto& q : star)
          starSheets.push_back(q.Sheet);
        std::sort(starSheets.begin(), starSheets.end());
        starSheets.erase(std::unique(starSheets.begin(), starSheets.end()), starSheets.end());
      };
      // A triangle of the star within Eps of x on the sheet (-1: none); 'first' is tried first: the
      // triangle that replaces the entry's hint keeps its id, and is most often still near. (Any
      // triangle within Eps will do: the order changes only the time taken.)
      auto near = [&](const Vec3& x, int sheet, int first) {
        double cl[3];
        auto within = [&](const StarTriangle& q) {
          return q.Sheet == sheet &&
            amTriangleLocator::ClosestPointOnTriangle(x.data(), q.X[0].data(), q.X[1].data(), q.X[2].data(), cl) <=
            eps2;
        };
        if (first >= 0)
          for (const auto& q : star)
            if (q.Id == first)
            {
              if (within(q))
                return q.Id;
              break;
            }
        for (const auto& q : star)
          if (q.Id != first && within(q))
            return q.Id;
        return -1;
      };
      for (int owner : { w, w == into ? from : -1 })
      {
        if (owner < 0)
          continue;
        const auto& cluster = this->Cluster[owner];
        for (size_t i = 0; i < cluster.size(); ++i)
        {
          const ClusterEntry& entry = cluster[i];
          const Vec3& x = this->RefPoints[entry.Point];
          if (entry.Sheet >= 0)
          {
            // (Membership of w's star, not the triangle's own record: a hint may be stale, and a
            // stale hint's triangle may lie on the other worker's side.)
            if (owner == w && entry.Hint >= 0 &&
              std::find(removed.begin(), removed.end(), entry.Hint) == removed.end() &&
              std::find(this->VT[w].begin(), this->VT[w].end(), entry.Hint) != this->VT[w].end())
              continue; // still within Eps of the same, untouched triangle
            gather();
            const int hit = near(x, entry.Sheet, entry.Hint);
            if (hit < 0)
              return false;
            pending.push_back({ owner, static_cast<int>(i), hit });
          }
          else
          {
            gather();
            for (int sheet : starSheets)
              if (near(x, sheet, -1) < 0)
                return false;
          }
        }
      }
    }
    return true;
  }
  /// The connected components of the live triangles when a collapse pass begins, and each one's
  /// number of vertices in zone 0, in zone 1 and in all. A collapse neither splits nor joins
  /// components and removes one vertex, so a worker bounds the size of a component from below
  /// without looking at it: what it had, less what this worker removed, less all it had on the
  /// other worker's side (the other worker removes only vertices there).
  std::vector<int> Component;
  std::vector<std::array<int, 3>> ComponentCount;
  void FindComponents()
  {
    std::vector<int> parent(this->P.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&parent](int v) {
      while (parent[v] != v)
        v = parent[v] = parent[parent[v]];
      return v;
    };
    for (const Tri& t : this->T)
      if (t.Alive)
        for (int k = 1; k < 3; ++k)
        {
          const int r0 = root(t.V[0]), r1 = root(t.V[k]);
          if (r0 != r1)
            parent[std::max(r0, r1)] = std::min(r0, r1);
        }
    this->Component.assign(this->P.size(), -1);
    this->ComponentCount.clear();
    std::vector<int> id(this->P.size(), -1);
    for (size_t v = 0; v < this->P.size(); ++v)
      if (this->VAlive[v] && !this->VT[v].empty())
      {
        int& c = id[root(static_cast<int>(v))];
        if (c < 0)
        {
          c = static_cast<int>(this->ComponentCount.size());
          this->ComponentCount.push_back({ 0, 0, 0 });
        }
        this->Component[v] = c;
        const int zone = this->ZoneAt(this->P[v]);
        if (zone < 2)
          ++this->ComponentCount[c][zone];
        ++this->ComponentCount[c][2];
      }
    for (Worker& w : this->Workers)
      w.Removed.assign(this->ComponentCount.size(), 0);
  }
  /// For the worker of zone CurrentZone: whether v's component surely has more than n live
  /// vertices, whatever the other worker has done meanwhile (see FindComponents).
  bool SurelyMoreThan(int v, int n) const
  {
    const int c = this->Component[v];
    if (c < 0)
      return false;
    const auto& count = this->ComponentCount[c];
    return count[2] - this->W().Removed[c] - count[1 - CurrentZone] > n;
  }
  /// Whether v's connected component has at most n vertices (searches no further than that).
  bool ComponentAtMost(int v, size_t n) const
  {
    std::vector<int> seen{ v }, next;
    for (size_t i = 0; i < seen.size(); ++i)
    {
      this->Neighbours(seen[i], next);
      for (int w : next)
        if (std::find(seen.begin(), seen.end(), w) == seen.end())
        {
          seen.push_back(w);
          if (seen.size() > n)
            return false;
        }
    }
    return true;
  }
  /// Whether (a, b) is an edge of a junction curve: other than two triangles, or two of
  /// different interfaces.
  bool IsFeature(int a, int b) const
  {
    std::vector<int> edge;
    this->EdgeTriangles(a, b, edge);
    return IsFeature(edge);
  }
  bool IsFeature(const std::vector<int>& edge) const
  {
    return edge.size() != 2 || this->T[edge[0]].Sheet != this->T[edge[1]].Sheet;
  }
  void EdgeTriangles(int a, int b, std::vector<int>& out) const
  {
    out.clear();
    for (int t : this->VT[a])
    {
      const int* v = this->T[t].V;
      if (v[0] == b || v[1] == b || v[2] == b)
        out.push_back(t);
    }
  }
  Vec3 Normal(int t) const
  {
    const int* v = this->T[t].V;
    return (this->P[v[1]] - this->P[v[0]]).cross(this->P[v[2]] - this->P[v[0]]);
  }
  void Detach(int t)
  {
    this->Unbin(t);
    this->T[t].Alive = false;
    for (int k = 0; k < 3; ++k)
    {
      auto& l = this->VT[this->T[t].V[k]];
      l.erase(std::remove(l.begin(), l.end(), t), l.end());
    }
  }
  int AddTriangle(int a, int b, int c, const Tri& like)
  {
    Tri t = like;
    t.V[0] = a;
    t.V[1] = b;
    t.V[2] = c;
    t.Alive = true;
    this->T.push_back(t);
    const int id = static_cast<int>(this->T.size()) - 1;
    this->VT[a].push_back(id);
    this->VT[b].push_back(id);
    this->VT[c].push_back(id);
    this->BinTriangle(id);
    return id;
  }

  /// Edge collapse: a disappears onto b, which stays where it is (half-edge collapse) or, given
  /// 'to' (two surface vertices only), moves there: a point of the input between them.
  bool Collapse(int a, int b, const Vec3* to = nullptr)
  {
    if (to && (this->Kind[a] != amSurfaceMesh::Surface || this->Kind[b] != amSurfaceMesh::Surface))
      return false;
    if (!this->VAlive[a] || !this->VAlive[b] || this->Kind[a] == amSurfaceMesh::Corner)
      return false;
    Worker& worker = this->W();
    auto &edge = worker.C.Edge, &na = worker.C.Na, &nb = worker.C.Nb, &common = worker.C.Common,
         &apex = worker.C.Apex, &changed = worker.C.Changed, &removed = worker.C.Removed,
         &sheets = worker.C.Sheets, &affected = worker.C.Affected;
    auto& ids = worker.C.Ids;
    auto& pos = worker.C.Pos;
    this->EdgeTriangles(a, b, edge);
    if (edge.empty())
      return false;
    const bool feature = this->IsFeature(edge);
    if ((this->Kind[a] == amSurfaceMesh::Curve) != feature)
      return false;
    // Link condition: the common neighbours are exactly the apexes of the edge's triangles.
    this->Neighbours(a, na);
    this->Neighbours(b, nb);
    common.clear();
    apex.clear();
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    for (int t : edge)
      for (int k = 0; k < 3; ++k)
        if (this->T[t].V[k] != a && this->T[t].V[k] != b)
          apex.push_back(this->T[t].V[k]);
    std::sort(apex.begin(), apex.end());
    apex.erase(std::unique(apex.begin(), apex.end()), apex.end());
    if (apex != common || apex.size() != edge.size())
      return false;
    // A closed fragment of five vertices or fewer is not collapsed further: as a tetrahedron it
    // is flat enough to turn inside out when its vertices are moved onto the input (seen on the
    // frog's thin organs: inverted bubbles whose labels then contradict the volume around them).
    // (A worker does not search: it only takes edges whose components are surely larger.)
    if (na.size() < 5 && (CurrentZone < 0 ? this->ComponentAtMost(a, 5) : !this->SurelyMoreThan(a, 5)))
      return false; // a and five neighbours are six already
    // The triangles that change: a's (a becomes b) and, when b moves, b's.
    const Vec3 x = to ? *to : this->P[b];
    const Mat3 mx = to ? Mat3(0.5 * (this->M[a] + this->M[b])) : this->M[b];
    changed.clear();
    removed = this->VT[a];
    for (int t : this->VT[a])
      if (std::find(edge.begin(), edge.end(), t) == edge.end())
        changed.push_back(t);
    if (to)
      for (int t : this->VT[b])
        if (std::find(edge.begin(), edge.end(), t) == edge.end())
        {
          changed.push_back(t);
          removed.push_back(t);
        }
    ids.clear();
    pos.clear();
    sheets.clear();
    for (int t : changed)
    {
      std::array<int, 3> v;
      std::array<Vec3, 3> p;
      int other[2], o = 0;
      for (int k = 0; k < 3; ++k)
      {
        v[k] = this->T[t].V[k] == a ? b : this->T[t].V[k];
        p[k] = v[k] == b ? x : this->P[v[k]];
        if (v[k] != b)
          other[o++] = v[k];
      }
      const Vec3 n0 = this->Normal(t), n1 = (p[1] - p[0]).cross(p[2] - p[0]);
      if (n1.norm() <= 1e-12 * n0.norm() || n0.normalized().dot(n1.normalized()) < 0.5)
        return false;
      if (MinAngle(p[0], p[1], p[2]) < SmallAngle) // a cap or needle no later flip may mend
        return false;
      if (!this->Allowed(b, this->T[t].Sheet))
        return false;
      if (this->Length(x, mx, other[0]) > LongEdge || this->Length(x, mx, other[1]) > LongEdge)
        return false;
      ids.push_back(v);
      pos.push_back(p);
      sheets.push_back(this->T[t].Sheet);
    }
    // The distance samples last: they cost most, and one of the checks above refuses a third of
    // the collapses tried (outer phantom surface). Where b stays, its edges stay.
    static const std::vector<int> none;
    if (!this->StarNear(ids, pos, sheets, b, to ? none : nb))
      return false;
    {
      // The input vertices a stood for must stay within Eps of the triangles of their interface
      // around b afterwards, and those of b and a's other neighbours within Eps of theirs (so no
      // patch of an interface can retract or vanish).
      affected = na;
      if (to)
        affected.insert(affected.end(), nb.begin(), nb.end());
      std::sort(affected.begin(), affected.end());
      affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
      affected.erase(std::remove(affected.begin(), affected.end(), a), affected.end());
      if (!this->ClustersStayNear(removed, ids, pos, sheets, changed, affected, a, b))
        return false;
      if (this->Crosses(ids, pos, removed))
        return false;
    }
    this->KeepHints();
    for (int t : edge)
      this->Detach(t);
    this->Cluster[b].insert(this->Cluster[b].end(), this->Cluster[a].begin(), this->Cluster[a].end());
    std::vector<ClusterEntry>().swap(this->Cluster[a]);
    for (int t : this->VT[a])
    {
      for (int k = 0; k < 3; ++k)
        if (this->T[t].V[k] == a)
          this->T[t].V[k] = b;
      this->VT[b].push_back(t);
    }
    this->VT[a].clear();
    this->VAlive[a] = 0;
    this->P[b] = x;
    this->M[b] = mx;
    this->Rebin(changed);
    ++worker.Collapses;
    if (CurrentZone >= 0)
      ++worker.Removed[this->Component[a]];
    for (int w : na)
      this->Touch(w);
    if (to)
      for (int w : nb)
        this->Touch(w);
    return true;
  }

  /// Collapse of an edge between two surface vertices into the point of the input nearest its
  /// middle (on the side its triangles face): where neither end can take the other's triangles
  /// without an edge longer than LongEdge, the middle often can (on the 1 mm phantom 11.1x fewer
  /// triangles than the input instead of 9.7x, at the same Hausdorff distance and angles).
  bool CollapseToMiddle(int a, int b, bool& outside)
  {
    outside = false;
    if (this->Kind[a] != amSurfaceMesh::Surface || this->Kind[b] != amSurfaceMesh::Surface)
      return false;
    Vec3 n = Vec3::Zero();
    for (int v : { a, b })
      for (int t : this->VT[v])
      {
        n += this->Normal(t);
        // Not beside a junction curve: moving b there made needles across the crease that no
        // insertion could bring back within Eps (2 mm phantom, uniform 4 mm: 0.61 for 0.5).
        for (int k = 0; k < 3; ++k)
          if (this->Kind[this->T[t].V[k]] != amSurfaceMesh::Surface)
            return false;
      }
    if (n.norm() == 0)
      return false;
    const Vec3 m = 0.5 * (this->P[a] + this->P[b]);
    double cl[3];
    vtkIdType tri;
    if (this->Ref[this->T[this->VT[a][0]].Sheet].ClosestPointFacing(m.data(), n.data(), cl, tri) ==
      std::numeric_limits<double>::infinity())
      return false;
    const Vec3 x(cl);
    if (CurrentZone >= 0 && this->ZoneAt(x) != CurrentZone)
    {
      outside = true;
      return false;
    }
    return this->Collapse(a, b, &x);
  }

  /// Vertices whose neighbourhood changed since the last collapse pass began: only edges at one
  /// of them are tried again (a refused collapse whose star did not change would be refused
  /// again, unless it was refused for crossing a triangle elsewhere that has since moved: such an
  /// edge waits until something changes next to it).
  std::vector<char> Dirty;
  /// The same since the last flip pass began: a flip pass after another tries only the edges at
  /// one of them (an edge whose two triangles did not change keeps its angles, and the angles
  /// refuse most flips).
  std::vector<char> FlipDirty;
  /// Both flags for every vertex (new vertices count as touched). Not on a worker: OnTwoWorkers
  /// calls it first.
  void SizeDirty()
  {
    if (this->Dirty.size() < this->P.size())
      this->Dirty.resize(this->P.size(), 1);
    if (this->FlipDirty.size() < this->P.size())
      this->FlipDirty.resize(this->P.size(), 1);
  }
  void Touch(int v)
  {
    if (static_cast<size_t>(v) >= std::min(this->Dirty.size(), this->FlipDirty.size()))
      this->SizeDirty();
    this->Dirty[v] = 1;
    this->FlipDirty[v] = 1;
  }
  int CollapsePass()
  {
    this->SizeDirty();
    // Shortest first, by classes of metric length a tenth wide, and within a class in the Morton
    // order of the edges' midpoints (cells the size of the bins): consecutive collapses then
    // read and change the same part of memory. (Edges in order of length alone were scattered
    // over the whole surface: most reads of a collapse's checks missed the caches.)
    struct Candidate
    {
      long long Class;
      unsigned long long Code;
      double Length;
      int A, B;
      bool operator<(const Candidate& o) const
      {
        return std::tie(this->Class, this->Code, this->Length, this->A, this->B) <
          std::tie(o.Class, o.Code, o.Length, o.A, o.B);
      }
      bool operator==(const Candidate& o) const { return this->A == o.A && this->B == o.B; }
    };
    // Gathered on the threads (each edge once from one of its triangles, as the half-edge
    // a -> b with a < b; a junction edge maybe more than once), sorted whole.
    vtkSMPThreadLocal<std::vector<Candidate>> found;
    vtkSMPTools::For(0, static_cast<vtkIdType>(this->T.size()), [&](vtkIdType t0, vtkIdType t1) {
      auto& local = found.Local();
      for (vtkIdType t = t0; t < t1; ++t)
      {
        if (!this->T[t].Alive)
          continue;
        for (int k = 0; k < 3; ++k)
        {
          const int a = this->T[t].V[k], b = this->T[t].V[(k + 1) % 3];
          if (a < b && (this->Dirty[a] || this->Dirty[b]))
          {
            const double L = this->Length(a, b);
            if (L < ShortEdge)
              local.push_back({ static_cast<long long>(L * 10.0),
                this->MortonCode(0.5 * (this->P[a] + this->P[b]), this->BinSize), L, a, b });
          }
        }
      }
    });
    std::vector<Candidate> cand;
    for (const auto& local : found)
      cand.insert(cand.end(), local.begin(), local.end());
    amThreading::Sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    std::fill(this->Dirty.begin(), this->Dirty.end(), 0);
    // Two workers, one on each side of the split plane (see OnTwoWorkers): a collapse changes
    // only the triangles, links, positions and clusters of the stars of a and b.
    this->FindComponents();
    return this->OnTwoWorkers(
      cand.size(),
      [&](size_t i) {
        const int za = this->ZoneAt(this->P[cand[i].A]), zb = this->ZoneAt(this->P[cand[i].B]);
        return za == zb ? za : 2;
      },
      [&](size_t i) {
        const int a = cand[i].A, b = cand[i].B;
        // Small fragments are left to the serial pass: there the test for them searches the
        // whole component.
        if (CurrentZone >= 0 &&
          (!this->StarsInZone(a, b, CurrentZone) || !this->SurelyMoreThan(a, 5) || !this->SurelyMoreThan(b, 5)))
          return this->VAlive[a] && this->VAlive[b] ? -1 : 0;
        return this->TryCollapse(a, b);
      });
  }

  /// Runs op on the items 0 .. n-1 on two workers, one on each side of the split plane, then
  /// serially. Each worker takes, in order, the items whose zone (zoneOf) is its side's; op
  /// returns 1 (done), 0 (refused) or -1 (left for the serial pass). A worker's op must change
  /// and read only what lies in its side's bins (the stars it changes, and the bins its
  /// crossing check reads): then neither worker reads what the other changes, and each side's
  /// result does not depend on the other's timing. The items left, and those in no zone (2),
  /// follow serially, in order. (The bins are exact, see BinnedIn: an entry in a worker's side
  /// names a triangle touching that side, which the other worker cannot change.)
  template <typename ZoneOfItem, typename Op>
  int OnTwoWorkers(size_t n, ZoneOfItem zoneOf, Op op)
  {
    this->SizeDirty(); // Touch must not resize them on a worker
    std::vector<char> later(n, 1);
    std::array<std::vector<size_t>, 2> side, taken; // taken: what each worker did not leave
    for (size_t i = 0; i < n; ++i)
    {
      const int z = zoneOf(i);
      if (z < 2)
        side[z].push_back(i);
    }
    std::array<int, 2> doneBy = { 0, 0 };
    vtkSMPTools::For(0, 2, 1, [&](vtkIdType z0, vtkIdType z1) {
      for (vtkIdType z = z0; z < z1; ++z)
      {
        const int worker = CurrentWorker, zone = CurrentZone;
        CurrentWorker = static_cast<int>(z);
        CurrentZone = static_cast<int>(z);
        int done = 0; // counted here, written once (the workers' items interleave)
        for (size_t i : side[z])
        {
          const int r = op(i);
          if (r >= 0)
            taken[z].push_back(i);
          done += r > 0;
        }
        doneBy[z] = done;
        CurrentWorker = worker;
        CurrentZone = zone;
      }
    });
    for (const auto& list : taken)
      for (size_t i : list)
        later[i] = 0;
    int done = doneBy[0] + doneBy[1];
    for (size_t i = 0; i < n; ++i)
      if (later[i])
        done += op(i) > 0;
    return done;
  }

  /// Whether the stars of a and b lie in zone z's bins.
  bool StarsInZone(int a, int b, int z) const
  {
    if (!this->VAlive[a] || !this->VAlive[b])
      return false;
    Vec3 lo = this->P[a], hi = this->P[a];
    for (int v : { a, b })
      for (int t : this->VT[v])
        for (int k = 0; k < 3; ++k)
        {
          lo = lo.cwiseMin(this->P[this->T[t].V[k]]);
          hi = hi.cwiseMax(this->P[this->T[t].V[k]]);
        }
    return this->BoxInZone(lo, hi, z);
  }

  /// The collapse of a short edge in one of its forms: 1 done, 0 refused, -1 left for the serial
  /// pass (a worker's collapse into a middle outside its zone).
  int TryCollapse(int a, int b)
  {
    if (!this->VAlive[a] || !this->VAlive[b] || this->Length(a, b) >= ShortEdge)
      return 0;
    // Remove the less constrained end first.
    if (this->Kind[a] <= this->Kind[b] ? (this->Collapse(a, b) || this->Collapse(b, a))
                                       : (this->Collapse(b, a) || this->Collapse(a, b)))
      return 1;
    bool outside = false;
    if (this->CollapseToMiddle(a, b, outside))
      return 1;
    return outside ? -1 : 0;
  }

  bool Flip(int a, int b)
  {
    std::vector<int> edge;
    this->EdgeTriangles(a, b, edge);
    if (this->IsFeature(edge))
      return false;
    // t1 = (a, b, c), t2 = (b, a, d) in their own orientation.
    int t1 = edge[0], t2 = edge[1];
    auto rotateTo = [&](int t, int first, int second) {
      const int* v = this->T[t].V;
      for (int k = 0; k < 3; ++k)
        if (v[k] == first && v[(k + 1) % 3] == second)
          return v[(k + 2) % 3];
      return -1;
    };
    int c = rotateTo(t1, a, b), d = rotateTo(t2, b, a);
    if (c < 0 || d < 0)
    {
      std::swap(t1, t2);
      c = rotateTo(t1, a, b);
      d = rotateTo(t2, b, a);
      if (c < 0 || d < 0)
        return false; // inconsistent orientation: leave it
    }
    if (c == d)
      return false;
    // The angles first: they refuse most edges, and cost less than the link test.
    const Vec3 &pa = this->P[a], &pb = this->P[b], &pc = this->P[c], &pd = this->P[d];
    const double before = std::min(MinAngle(pa, pb, pc), MinAngle(pb, pa, pd));
    const double after = std::min(MinAngle(pa, pd, pc), MinAngle(pd, pb, pc));
    if (after <= before + 1e-3)
      return false;
    std::vector<int> nc;
    this->Neighbours(c, nc);
    if (std::binary_search(nc.begin(), nc.end(), d))
      return false;
    const Vec3 n0 = (this->Normal(t1).normalized() + this->Normal(t2).normalized()).normalized();
    const Vec3 n1 = (pd - pa).cross(pc - pa), n2 = (pb - pd).cross(pc - pd);
    if (n1.norm() == 0 || n2.norm() == 0 || n1.normalized().dot(n0) < 0.9 || n2.normalized().dot(n0) < 0.9)
      return false;
    const int sheet = this->T[t1].Sheet;
    if (!this->TriangleNear(sheet, pa, pd, pc) || !this->TriangleNear(sheet, pd, pb, pc))
      return false;
    // The two triangles keep their ids (a worker must not add triangles): t1 becomes (a, d, c)
    // and t2 (d, b, c), with t1's labels.
    if (!this->ClustersStayNear({ t1, t2 }, { { a, d, c }, { d, b, c } }, { { pa, pd, pc }, { pd, pb, pc } },
          { sheet, sheet }, { t1, t2 }, { a, b, c, d }))
      return false;
    if (this->Crosses({ { a, d, c }, { d, b, c } }, { { pa, pd, pc }, { pd, pb, pc } }, { t1, t2 }))
      return false;
    this->KeepHints();
    const std::vector<int> pair = { t1, t2 };
    auto drop = [this](int v, int t) {
      auto& l = this->VT[v];
      l.erase(std::remove(l.begin(), l.end(), t), l.end());
    };
    drop(a, t2);
    drop(b, t1);
    this->VT[c].push_back(t2);
    this->VT[d].push_back(t1);
    const int v1[3] = { a, d, c }, v2[3] = { d, b, c };
    std::copy(v1, v1 + 3, this->T[t1].V);
    std::copy(v2, v2 + 3, this->T[t2].V);
    std::copy(this->T[t1].Labels, this->T[t1].Labels + 2, this->T[t2].Labels);
    this->Rebin(pair);
    ++this->W().Flips;
    for (int w : { a, b, c, d })
      this->Touch(w);
    return true;
  }

  /// Every edge flipped where that makes the smallest angle of its two triangles larger; on two
  /// workers (see OnTwoWorkers: a flip changes the two triangles of the edge, in the stars of its
  /// ends). 'onlyTouched': only the edges at a vertex touched since the last flip pass began.
  int FlipPass(bool onlyTouched = false)
  {
    this->SizeDirty();
    this->RebuildBinsIfStale();
    // Each edge once, in the Morton order of its midpoint (see CollapsePass): an edge of two
    // triangles of one orientation is the half-edge a -> b with a < b of one of them; a junction
    // edge may come more than once, and then its copies are neighbours in that order. (An edge
    // whose two triangles disagree on their orientation may be missed: Flip leaves those.)
    // (Gathered on the threads, sorted whole.)
    using Edge = std::pair<unsigned long long, std::pair<int, int>>;
    vtkSMPThreadLocal<std::vector<Edge>> found;
    vtkSMPTools::For(0, static_cast<vtkIdType>(this->T.size()), [&](vtkIdType t0, vtkIdType t1) {
      auto& local = found.Local();
      for (vtkIdType t = t0; t < t1; ++t)
        if (this->T[t].Alive)
          for (int k = 0; k < 3; ++k)
          {
            const int a = this->T[t].V[k], b = this->T[t].V[(k + 1) % 3];
            if ((a < b || this->Kind[a] != amSurfaceMesh::Surface || this->Kind[b] != amSurfaceMesh::Surface) &&
              (!onlyTouched || this->FlipDirty[a] || this->FlipDirty[b]))
              local.push_back({ this->MortonCode(0.5 * (this->P[a] + this->P[b]), this->BinSize),
                { std::min(a, b), std::max(a, b) } });
          }
    });
    std::vector<Edge> order;
    for (const auto& local : found)
      order.insert(order.end(), local.begin(), local.end());
    std::fill(this->FlipDirty.begin(), this->FlipDirty.end(), 0);
    amThreading::Sort(order.begin(), order.end());
    order.erase(std::unique(order.begin(), order.end()), order.end());
    std::vector<std::pair<int, int>> edges(order.size());
    for (size_t i = 0; i < order.size(); ++i)
      edges[i] = order[i].second;
    return this->OnTwoWorkers(
      edges.size(),
      [&](size_t i) {
        const int za = this->ZoneAt(this->P[edges[i].first]), zb = this->ZoneAt(this->P[edges[i].second]);
        return za == zb ? za : 2;
      },
      [&](size_t i) {
        const int a = edges[i].first, b = edges[i].second;
        if (CurrentZone >= 0 && !this->StarsInZone(a, b, CurrentZone))
          return this->VAlive[a] && this->VAlive[b] ? -1 : 0;
        return this->Flip(a, b) ? 1 : 0;
      });
  }

  /// Every surface vertex moved halfway to the centroid of its neighbours, along the surface,
  /// then onto the input (where Move allows it); on two workers (see OnTwoWorkers: a move
  /// changes the triangles of v's star and the clusters of v and its neighbours).
  int RelaxPass()
  {
    this->RebuildBinsIfStale();
    // In the Morton order of the vertices (see CollapsePass).
    std::vector<std::pair<unsigned long long, int>> order;
    for (size_t v = 0; v < this->P.size(); ++v)
      if (this->VAlive[v] && this->Kind[v] == amSurfaceMesh::Surface && !this->VT[v].empty())
        order.push_back({ this->MortonCode(this->P[v], this->BinSize), static_cast<int>(v) });
    amThreading::Sort(order.begin(), order.end());
    return this->OnTwoWorkers(
      order.size(), [&](size_t i) { return this->ZoneAt(this->P[order[i].second]); },
      [&](size_t i) { return this->Relax(order[i].second); });
  }
  /// One vertex of RelaxPass: 1 moved, 0 not, -1 left for the serial pass (a worker's vertex whose
  /// star or new place is not all on its side).
  int Relax(int v)
  {
    if (!this->VAlive[v] || this->Kind[v] != amSurfaceMesh::Surface || this->VT[v].empty())
      return 0;
    if (CurrentZone >= 0 && !this->StarsInZone(v, v, CurrentZone))
      return -1;
    thread_local std::vector<int> ring;
    this->Neighbours(v, ring);
    Vec3 centroid = Vec3::Zero(), n = Vec3::Zero();
    for (int q : ring)
      centroid += this->P[q];
    centroid /= static_cast<double>(ring.size());
    for (int t : this->VT[v])
      n += this->Normal(t);
    if (n.norm() == 0)
      return 0;
    n.normalize();
    Vec3 x = this->P[v] + 0.5 * ((centroid - this->P[v]) - (centroid - this->P[v]).dot(n) * n);
    const int sheet = this->T[this->VT[v][0]].Sheet;
    double cl[3];
    vtkIdType tri;
    if (this->Ref[sheet].ClosestPointFacing(x.data(), n.data(), cl, tri) == std::numeric_limits<double>::infinity())
      return 0;
    x = Vec3(cl);
    if (CurrentZone >= 0 && this->ZoneAt(x) != CurrentZone)
      return -1;
    return this->Move(v, x, true) ? 1 : 0;
  }

  /// Where the point x of the input is nearest to a surface vertex of triangle t (it lies above
  /// a vertex where the surface bends, not above a triangle to insert it into): move that vertex
  /// to x. Returns whether it was done.
  bool MoveVertexNearest(int t, const Vec3& x)
  {
    if (!this->T[t].Alive)
      return false;
    const int* w = this->T[t].V;
    double cl[3];
    amTriangleLocator::ClosestPointOnTriangle(x.data(), this->P[w[0]].data(), this->P[w[1]].data(), this->P[w[2]].data(), cl);
    const double longest =
      std::max({ (this->P[w[1]] - this->P[w[0]]).norm(), (this->P[w[2]] - this->P[w[1]]).norm(), (this->P[w[0]] - this->P[w[2]]).norm() });
    for (int k = 0; k < 3; ++k)
      if ((Vec3(cl) - this->P[w[k]]).norm() < 0.05 * longest)
        return this->Move(w[k], x, false);
    return false;
  }

  /// Move surface vertex v to x (a point of the input) unless a triangle around it would turn
  /// over, leave its interface by more than Eps, carry an input point too far, cross another, or
  /// get a smaller angle than before ('relax') or than min(before, SmallAngle) (otherwise).
  bool Move(int v, const Vec3& x, bool relax)
  {
    if (this->Kind[v] != amSurfaceMesh::Surface || this->VT[v].empty())
      return false;
    double before = M_PI, after = M_PI;
    std::vector<std::array<int, 3>> ids;
    std::vector<std::array<Vec3, 3>> pos;
    std::vector<int> sheets;
    for (int t : this->VT[v])
    {
      std::array<Vec3, 3> p, q;
      for (int k = 0; k < 3; ++k)
      {
        p[k] = this->P[this->T[t].V[k]];
        q[k] = this->T[t].V[k] == v ? x : p[k];
      }
      before = std::min(before, MinAngle(p[0], p[1], p[2]));
      after = std::min(after, MinAngle(q[0], q[1], q[2]));
      const Vec3 n0 = (p[1] - p[0]).cross(p[2] - p[0]), n1 = (q[1] - q[0]).cross(q[2] - q[0]);
      if (n1.norm() == 0 || n0.normalized().dot(n1.normalized()) < 0.7)
        return false;
      ids.push_back({ this->T[t].V[0], this->T[t].V[1], this->T[t].V[2] });
      pos.push_back(q);
      sheets.push_back(this->T[t].Sheet);
    }
    if (after < (relax ? before : std::min(before, SmallAngle)))
      return false;
    static const std::vector<int> none;
    if (!this->StarNear(ids, pos, sheets, v, none))
      return false;
    std::vector<int> ring;
    this->Neighbours(v, ring);
    ring.push_back(v);
    if (!this->ClustersStayNear(this->VT[v], ids, pos, sheets, this->VT[v], ring) ||
      this->Crosses(ids, pos, this->VT[v]))
      return false;
    this->KeepHints();
    this->P[v] = x;
    this->Rebin(this->VT[v]);
    ++this->W().Moves;
    for (int w : ring)
      this->Touch(w);
    return true;
  }

  // What the last Measure saw: the next one measures again only what changed since (the input is
  // fixed, so a triangle with the same vertices at the same places has the same distances, and an
  // input sample whose nearest triangle is unchanged can only have come nearer to a new one).
  struct MeasureCache
  {
    bool Valid = false;
    std::vector<std::array<int, 4>> Tri; // per triangle slot: vertices and sheet (sheet -1: dead)
    std::vector<Vec3> P;                 // vertex positions
    std::vector<double> Worst, Gap;      // per triangle slot: remeshed -> input
    std::vector<Vec3> Far;
    std::vector<int> Edge;
    std::vector<std::vector<double>> D2; // per sheet, per input sample: squared distance ...
    std::vector<std::vector<int>> At;    // ... and the nearest triangle's slot (-1: none)
  } Cache;
  bool Unchanged(size_t t) const
  {
    const MeasureCache& c = this->Cache;
    if (!c.Valid || t >= c.Tri.size() || !this->T[t].Alive || c.Tri[t][3] != this->T[t].Sheet)
      return false;
    for (int k = 0; k < 3; ++k)
    {
      const int v = this->T[t].V[k];
      if (v != c.Tri[t][k] || static_cast<size_t>(v) >= c.P.size() || !(this->P[v] == c.P[v]))
        return false;
    }
    return true;
  }

  /// The two-sided distance per interface; fills the points to insert where it exceeds Eps.
  double Measure(double& upperBound, std::vector<std::pair<int, Vec3>>& insert, std::vector<int>& edgeOf)
  {
    edgeOf.clear();
    const int nSheets = static_cast<int>(this->Ref.size());
    const size_t nt = this->T.size();
    std::vector<char> same(nt, 0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(nt), [&](vtkIdType t0, vtkIdType t1) {
      for (vtkIdType t = t0; t < t1; ++t)
        same[t] = this->Unchanged(static_cast<size_t>(t)) ? 1 : 0;
    });
    // Per sheet: the whole current surface, and the triangles changed since the last Measure.
    std::vector<amTriangleLocator> cur(static_cast<size_t>(nSheets)), changed(static_cast<size_t>(nSheets));
    // Where the changed triangles are: an input sample elsewhere keeps its distance (the later
    // measures change a few triangles; querying every sample cost a tenth of a second each).
    std::vector<NearCells> changedNear(static_cast<size_t>(nSheets));
    std::vector<std::vector<int>> ids(static_cast<size_t>(nSheets)), changedIds(static_cast<size_t>(nSheets));
    {
      std::vector<std::vector<std::array<vtkIdType, 3>>> tris(static_cast<size_t>(nSheets)),
        changedTris(static_cast<size_t>(nSheets));
      std::vector<std::array<double, 3>> pts(this->P.size());
      for (size_t i = 0; i < this->P.size(); ++i)
        pts[i] = { this->P[i].x(), this->P[i].y(), this->P[i].z() };
      for (size_t t = 0; t < nt; ++t)
        if (this->T[t].Alive)
        {
          const std::array<vtkIdType, 3> v = { this->T[t].V[0], this->T[t].V[1], this->T[t].V[2] };
          tris[this->T[t].Sheet].push_back(v);
          ids[this->T[t].Sheet].push_back(static_cast<int>(t));
          if (!same[t])
          {
            changedTris[this->T[t].Sheet].push_back(v);
            changedIds[this->T[t].Sheet].push_back(static_cast<int>(t));
          }
        }
      // The whole surface on one thread, what changed on the other (read only where the cache
      // is valid: the first Measure queries the whole surface everywhere).
      vtkSMPTools::For(0, 2, 1, [&](vtkIdType j0, vtkIdType j1) {
        for (vtkIdType j = j0; j < j1; ++j)
          for (int s = 0; s < nSheets; ++s)
            if (j == 0)
              cur[s].Build(pts, tris[s]);
            else if (this->Cache.Valid)
            {
              changed[s].Build(pts, changedTris[s]);
              changedNear[s].Build(this->RefSamples[s], 2.0 * this->Eps, pts, changedTris[s]);
            }
      });
    }
    MeasureCache& cache = this->Cache;
    cache.D2.resize(static_cast<size_t>(nSheets));
    cache.At.resize(static_cast<size_t>(nSheets));
    double worst = 0, gap = 0;
    insert.clear();
    std::vector<char> used(nt, 0);
    const double eps2 = this->Eps * this->Eps, near2 = 16.0 * eps2;
    // Input -> remeshed.
    for (int s = 0; s < nSheets; ++s)
    {
      const auto& samples = this->RefSamples[s];
      std::vector<double>& d2 = cache.D2[s];
      std::vector<int>& at = cache.At[s];
      const bool known = cache.Valid && d2.size() == samples.size();
      if (!known)
      {
        d2.assign(samples.size(), 0.0);
        at.assign(samples.size(), -1);
      }
      vtkSMPTools::For(0, static_cast<vtkIdType>(samples.size()), [&](vtkIdType i0, vtkIdType i1) {
        double cl[3];
        vtkIdType a;
        for (vtkIdType i = i0; i < i1; ++i)
          if (known && at[i] >= 0 && same[at[i]])
          {
            if (!changedNear[s].MayComeNearer(samples[i], d2[i]))
              continue;
            const double q = changed[s].ClosestPointWithin(samples[i].data(), d2[i], cl, a);
            if (q < d2[i] && a >= 0)
            {
              d2[i] = q;
              at[i] = changedIds[s][a];
            }
          }
          else
          {
            // Within a bound first (only the bins within reach are searched), then everywhere.
            d2[i] = cur[s].ClosestPointWithin(samples[i].data(), near2, cl, a);
            if (a < 0)
              d2[i] = cur[s].ClosestPoint(samples[i].data(), cl, a);
            at[i] = a >= 0 ? ids[s][a] : -1;
          }
      });
      for (size_t i = 0; i < samples.size(); ++i)
      {
        worst = std::max(worst, std::sqrt(d2[i]));
        if (d2[i] > eps2 && at[i] >= 0)
        {
          const int t = at[i];
          if (!used[t])
          {
            used[t] = 1;
            insert.push_back({ t, samples[i] });
            edgeOf.push_back(-1);
          }
        }
      }
    }
    // Remeshed -> input: a grid of points on every triangle, spacing at most Eps (again only on
    // the triangles that changed).
    std::vector<int> alive, todo;
    for (size_t t = 0; t < nt; ++t)
      if (this->T[t].Alive)
      {
        alive.push_back(static_cast<int>(t));
        if (!same[t])
          todo.push_back(static_cast<int>(t));
      }
    cache.Worst.resize(nt, 0.0);
    cache.Gap.resize(nt, 0.0);
    cache.Far.resize(nt, Vec3::Zero());
    cache.Edge.resize(nt, -1); // the far sample lies on edge k (V[k], V[k+1]), or -1
    vtkSMPTools::For(0, static_cast<vtkIdType>(todo.size()), [&](vtkIdType i0, vtkIdType i1) {
      double cl[3];
      vtkIdType tt;
      for (vtkIdType i = i0; i < i1; ++i)
      {
        const int slot = todo[i];
        const Tri& t = this->T[slot];
        const Vec3 &a = this->P[t.V[0]], &b = this->P[t.V[1]], &c = this->P[t.V[2]];
        const double longest = std::max({ (b - a).norm(), (c - b).norm(), (a - c).norm() });
        // Spacing Eps, at most 12 intervals per edge (the gap enters the upper bound).
        const int n = std::min(12, std::max(2, static_cast<int>(std::ceil(longest / this->Eps))));
        double w = 0;
        Vec3 far = a, farSample = a;
        int onEdge = -1;
        vtkIdType hint = -1; // the input triangle the last sample found near
        auto visit = [&](const Vec3& x, int edge) {
          // Only a sample farther than the farthest so far changes anything: the cheap test first.
          if (w > 0 && this->Ref[t.Sheet].WithinDistance(x.data(), w, nullptr, &hint))
            return;
          double d = this->Ref[t.Sheet].ClosestPointWithin(x.data(), near2, cl, tt);
          if (tt < 0)
            d = this->Ref[t.Sheet].ClosestPoint(x.data(), cl, tt);
          hint = tt;
          if (d > w)
          {
            w = d;
            far = Vec3(cl);
            farSample = x;
            onEdge = edge;
          }
        };
        // The centroid and the edge midpoints first, which the grid misses when n is odd or not a
        // multiple of three (SurfaceDistance samples them: its figure can be no larger than ours).
        // The distance is largest inside a triangle, mostly near its centroid, and least at its
        // vertices (on the input): from there, most grid points pass the cheap test.
        visit((a + b + c) / 3.0, -1);
        visit(0.5 * (a + b), 0);
        visit(0.5 * (b + c), 1);
        visit(0.5 * (c + a), 2);
        // Row by row, every other row backwards: each sample next to the last one, whose input
        // triangle (the hint) is then mostly the one the cheap test needs.
        for (int u = 0; u <= n; ++u)
          for (int i = 0; u + i <= n; ++i)
          {
            const int v = u % 2 ? n - u - i : i;
            visit(a + (b - a) * (static_cast<double>(u) / n) + (c - a) * (static_cast<double>(v) / n),
              v == 0 ? 0 : (u + v == n ? 1 : (u == 0 ? 2 : -1)));
          }
        // The point to insert: on the side of the input facing the way the triangle faces.
        if (w > this->Eps * this->Eps)
        {
          const Vec3 normal = (b - a).cross(c - a);
          if (this->Ref[t.Sheet].ClosestPointFacing(farSample.data(), normal.data(), cl, tt) <
            std::numeric_limits<double>::infinity())
            far = Vec3(cl);
        }
        cache.Worst[slot] = std::sqrt(w);
        cache.Far[slot] = far;
        cache.Edge[slot] = onEdge;
        cache.Gap[slot] = longest / n / std::sqrt(3.0);
      }
    });
    for (int t : alive)
    {
      worst = std::max(worst, cache.Worst[t]);
      gap = std::max(gap, cache.Gap[t]);
      if (cache.Worst[t] > this->Eps && !used[t])
      {
        used[t] = 1;
        insert.push_back({ t, cache.Far[t] });
        edgeOf.push_back(cache.Edge[t]);
      }
    }
    // What this Measure saw.
    cache.Tri.resize(nt);
    for (size_t t = 0; t < nt; ++t)
      cache.Tri[t] = { this->T[t].V[0], this->T[t].V[1], this->T[t].V[2], this->T[t].Alive ? this->T[t].Sheet : -1 };
    cache.P = this->P;
    cache.Valid = true;
    upperBound = worst + gap;
    return worst;
  }

  /// A copy of the state the operations change, for an undo by Restore: the input (locators,
  /// samples, curves), the bins and the Measure cache are not copied (the input never changes;
  /// nothing but the output is made after a Restore).
  Remesher Snapshot()
  {
    Remesher keep;
    this->SwapUncopied(keep);
    Remesher copy = *this;
    this->SwapUncopied(keep);
    return copy;
  }
  void Restore(Remesher&& snapshot)
  {
    this->SwapUncopied(snapshot);
    *this = std::move(snapshot);
  }
  void SwapUncopied(Remesher& o)
  {
    std::swap(this->Ref, o.Ref);
    std::swap(this->RefSamples, o.RefSamples);
    std::swap(this->RefPoints, o.RefPoints);
    std::swap(this->InputSheets, o.InputSheets);
    std::swap(this->CurveNeighbours, o.CurveNeighbours);
    std::swap(this->Bins, o.Bins);
    std::swap(this->BinnedIn, o.BinnedIn);
    std::swap(this->BinnedBox, o.BinnedBox);
    std::swap(this->Cache, o.Cache);
  }

  /// Split edge k of triangle t (and every triangle on that edge) at x, unless the new triangles
  /// would cross another triangle. Returns whether it was done.
  bool SplitEdge(int t, int k, Vec3 x)
  {
    this->W().LastHit = -1;
    if (!this->T[t].Alive)
      return false;
    const int a = this->T[t].V[k], b = this->T[t].V[(k + 1) % 3];
    std::vector<int> edge;
    this->EdgeTriangles(a, b, edge);
    const bool feature = this->IsFeature(edge);
    int curvePoint = -1;
    if (feature)
    {
      // A junction edge is split at the input curve vertex nearest its midpoint (a point of one
      // interface off the curve would fold the others).
      if (this->Anchor[a] < 0 || this->Anchor[b] < 0)
        return false;
      const double length = (this->P[b] - this->P[a]).norm();
      curvePoint = this->CurveMiddle(this->Anchor[a], this->Anchor[b], 4.0 * length);
      if (curvePoint < 0)
        return false;
      for (int e : edge)
        if (!std::binary_search(this->InputSheets[curvePoint].begin(), this->InputSheets[curvePoint].end(),
              this->T[e].Sheet))
          return false;
      x = this->RefPoints[curvePoint];
    }
    const int v = static_cast<int>(this->P.size());
    struct Half
    {
      int P, Q, C;
    };
    std::vector<Half> halves;
    std::vector<std::array<int, 3>> ids;
    std::vector<std::array<Vec3, 3>> pos;
    for (int e : edge)
    {
      const Tri& like = this->T[e];
      int i = 0;
      while (!(like.V[i] == a || like.V[i] == b) || !(like.V[(i + 1) % 3] == a || like.V[(i + 1) % 3] == b))
        ++i;
      const Half h{ like.V[i], like.V[(i + 1) % 3], like.V[(i + 2) % 3] };
      halves.push_back(h);
      ids.push_back({ h.P, v, h.C });
      pos.push_back({ this->P[h.P], x, this->P[h.C] });
      ids.push_back({ v, h.Q, h.C });
      pos.push_back({ x, this->P[h.Q], this->P[h.C] });
    }
    for (const auto& q : pos)
      if (MinAngle(q[0], q[1], q[2]) < MinimumNewAngle)
        return false;
    if (this->Crosses(ids, pos, edge))
      return false;
    this->P.push_back(x);
    this->M.push_back(0.5 * (this->M[a] + this->M[b]));
    this->Kind.push_back(feature ? amSurfaceMesh::Curve : amSurfaceMesh::Surface);
    this->Anchor.push_back(curvePoint);
    this->VAlive.push_back(1);
    this->VT.emplace_back();
    this->Cluster.emplace_back();
    for (size_t n = 0; n < edge.size(); ++n)
    {
      const Tri like = this->T[edge[n]];
      this->Detach(edge[n]);
      this->AddTriangle(halves[n].P, v, halves[n].C, like);
      this->AddTriangle(v, halves[n].Q, halves[n].C, like);
    }
    return true;
  }

  /// Split the longest edge of triangle t at the point of the input nearest its midpoint, then
  /// flip around the new vertex: how the distance bound is restored where it is exceeded, and
  /// where an insertion was refused because it would cross another part of the surface (both
  /// come closer to their own input surfaces, which do not cross). Returns the splits done.
  int Refine(int t)
  {
    if (t < 0 || !this->T[t].Alive)
      return 0;
    // The longest edge first; where that split is refused, a junction edge of t (it can hold the
    // input curve vertex that a split of the longest edge would fold over; splitting a shorter
    // edge inside the interface instead only made fans of ever shorter edges).
    std::array<std::pair<double, int>, 3> order;
    for (int e = 0; e < 3; ++e)
      order[e] = { -(this->P[this->T[t].V[(e + 1) % 3]] - this->P[this->T[t].V[e]]).norm(), e };
    std::sort(order.begin(), order.end());
    // The input point on the side facing the way the triangle faces (in a thin part the nearest
    // input point can lie on the other side, and refining towards it crumples the surface).
    const Vec3 n = this->Normal(t);
    for (const auto& [length, k] : order)
    {
      if (k != order[0].second && !this->IsFeature(this->T[t].V[k], this->T[t].V[(k + 1) % 3]))
        continue;
      const Vec3 mid = 0.5 * (this->P[this->T[t].V[k]] + this->P[this->T[t].V[(k + 1) % 3]]);
      double cl[3];
      vtkIdType tri;
      if (this->Ref[this->T[t].Sheet].ClosestPointFacing(mid.data(), n.data(), cl, tri) ==
          std::numeric_limits<double>::infinity() ||
        !this->SplitEdge(t, k, Vec3(cl)))
        continue;
      this->FlipAround(static_cast<int>(this->P.size()) - 1);
      return 1;
    }
    return 0;
  }

  /// Live triangles with an angle under SmallAngle, and the shortest live edge.
  void AngleSummary(long long& small, double& shortest) const
  {
    small = 0;
    shortest = std::numeric_limits<double>::infinity();
    for (const Tri& t : this->T)
      if (t.Alive)
      {
        const Vec3 &a = this->P[t.V[0]], &b = this->P[t.V[1]], &c = this->P[t.V[2]];
        small += MinAngle(a, b, c) < SmallAngle;
        shortest = std::min({ shortest, (b - a).norm(), (c - b).norm(), (a - c).norm() });
      }
  }

  /// Removes triangles with an angle under SmallAngle where an operation that keeps the other
  /// guarantees allows it: the flip of a cap's longest edge, else the collapse of the cap's apex
  /// (or of the needle's short edge) into a neighbour. Caps arise where the Hausdorff insertions
  /// refine along a crease of the input (the cut end of a vessel), which flips cannot cross.
  /// Returns the number of operations done.
  int SmallAngleCleanup()
  {
    int done = 0;
    for (size_t t = 0; t < this->T.size(); ++t)
    {
      if (!this->T[t].Alive)
        continue;
      const int* w = this->T[t].V;
      double angle[3];
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 u = this->P[w[(k + 1) % 3]] - this->P[w[k]], v = this->P[w[(k + 2) % 3]] - this->P[w[k]];
        angle[k] = std::acos(std::max(-1.0, std::min(1.0, u.dot(v) / (u.norm() * v.norm()))));
      }
      const int small = static_cast<int>(std::min_element(angle, angle + 3) - angle);
      if (!(angle[small] < SmallAngle))
        continue;
      const int large = static_cast<int>(std::max_element(angle, angle + 3) - angle);
      const int apex = w[large], a = w[(large + 1) % 3], b = w[(large + 2) % 3];
      bool ok = false;
      if (angle[large] > 0.5 * M_PI)
      {
        // A cap: its longest edge (a, b) faces the obtuse apex, which goes to the nearer end.
        const bool aNearer = (this->P[apex] - this->P[a]).norm() < (this->P[apex] - this->P[b]).norm();
        ok = this->Flip(std::min(a, b), std::max(a, b)) || this->Collapse(apex, aNearer ? a : b) ||
          this->Collapse(apex, aNearer ? b : a);
      }
      else
      {
        // A needle: its short edge is opposite the small angle.
        const int p = w[(small + 1) % 3], q = w[(small + 2) % 3];
        ok = this->Kind[p] <= this->Kind[q] ? (this->Collapse(p, q) || this->Collapse(q, p))
                                            : (this->Collapse(q, p) || this->Collapse(p, q));
      }
      done += ok;
    }
    return done;
  }

  /// Flip the edges opposite vertex v where that improves the angles.
  void FlipAround(int v)
  {
    std::vector<std::pair<int, int>> link;
    for (int t : this->VT[v])
      for (int k = 0; k < 3; ++k)
        if (this->T[t].V[k] == v)
          link.emplace_back(this->T[t].V[(k + 1) % 3], this->T[t].V[(k + 2) % 3]);
    for (const auto& e : link)
      this->Flip(e.first, e.second);
  }

  /// Insert x into triangle t (1 -> 3), then improve the neighbourhood by flips; refused when the
  /// new triangles would cross another triangle. A point that falls near an edge of t (a new
  /// triangle would get under 10 % of t's area) splits that edge instead, so no sliver triangle
  /// appears. Returns whether it was done.
  bool Insert(int t, Vec3 x)
  {
    this->W().LastHit = -1;
    if (!this->T[t].Alive)
      return false;
    const Tri like = this->T[t];
    const int v = static_cast<int>(this->P.size());
    const int* w = like.V;
    {
      const Vec3 n = (this->P[w[1]] - this->P[w[0]]).cross(this->P[w[2]] - this->P[w[0]]);
      int k = -1;
      double smallest = 0.1;
      for (int e = 0; e < 3; ++e)
      {
        const Vec3& p = this->P[w[e]];
        const double fraction = n.dot((this->P[w[(e + 1) % 3]] - p).cross(x - p)) / n.squaredNorm();
        if (fraction < smallest)
        {
          smallest = fraction;
          k = e;
        }
      }
      if (k >= 0)
      {
        // Only where x lies beside the edge's middle part; near a corner, neither split is good.
        const Vec3& p = this->P[w[k]];
        const Vec3 e = this->P[w[(k + 1) % 3]] - p;
        const double along = e.dot(x - p) / e.squaredNorm();
        if (along >= 0.15 && along <= 0.85 && this->SplitEdge(t, k, x))
        {
          this->FlipAround(static_cast<int>(this->P.size()) - 1);
          return true;
        }
        // Beside a junction edge that is an edge of the input curve (nothing to split it at),
        // where the interface bulges beyond the curve's chord: insert inside the triangle,
        // moved towards the opposite vertex and put back on the input.
        if (!this->IsFeature(w[k], w[(k + 1) % 3]))
          return false;
        const Vec3& o = this->P[w[(k + 2) % 3]];
        x += (0.2 - smallest) / (1.0 - smallest) * (o - x);
        double cl[3];
        vtkIdType tri;
        if (this->Ref[like.Sheet].ClosestPointFacing(x.data(), n.data(), cl, tri) ==
          std::numeric_limits<double>::infinity())
          return false;
        x = Vec3(cl);
        for (int e = 0; e < 3; ++e)
        {
          const Vec3& q = this->P[w[e]];
          if (n.dot((this->P[w[(e + 1) % 3]] - q).cross(x - q)) / n.squaredNorm() < 0.05)
            return false;
        }
      }
    }
    for (int e = 0; e < 3; ++e)
      if (MinAngle(this->P[w[e]], this->P[w[(e + 1) % 3]], x) < MinimumNewAngle)
        return false;
    if (this->Crosses({ { w[0], w[1], v }, { w[1], w[2], v }, { w[2], w[0], v } },
          { { this->P[w[0]], this->P[w[1]], x }, { this->P[w[1]], this->P[w[2]], x },
            { this->P[w[2]], this->P[w[0]], x } },
          { t }))
      return false;
    this->P.push_back(x);
    Mat3 m = (this->M[like.V[0]] + this->M[like.V[1]] + this->M[like.V[2]]) / 3.0;
    this->M.push_back(m);
    this->Kind.push_back(amSurfaceMesh::Surface);
    this->Anchor.push_back(-1);
    this->VAlive.push_back(1);
    this->VT.emplace_back();
    this->Cluster.emplace_back();
    this->Detach(t);
    this->AddTriangle(like.V[0], like.V[1], v, like);
    this->AddTriangle(like.V[1], like.V[2], v, like);
    this->AddTriangle(like.V[2], like.V[0], v, like);
    this->FlipAround(v);
    return true;
  }
};
}

amMetricRemeshing::amMetricRemeshing()
  : Tolerance(0.2)
  , TargetSize(0.0)
  , NumberOfIterations(3)
  , Hausdorff(0)
  , HausdorffUpperBound(0)
  , InsertedPoints(0)
{
  amThreading::Initialize();
}

amMetricRemeshing::~amMetricRemeshing() = default;

int amMetricRemeshing::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  amSurfaceMesh mesh;
  std::string why;
  if (!mesh.Build(input, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  vtkDataArray* metric = input->GetPointData()->GetArray("Metric");
  if (this->TargetSize <= 0 && (!metric || metric->GetNumberOfComponents() != 6))
  {
    vtkErrorMacro("The input has no 6-component point data \"Metric\" (run Curvature Metric first) and no "
                  "TargetSize is set.");
    return 0;
  }
  if (mesh.Labels.empty())
    for (size_t e = 0; e < mesh.Edges.size(); ++e)
      if (mesh.EdgeTriangleStart[e + 1] - mesh.EdgeTriangleStart[e] > 2)
      {
        vtkErrorMacro("The surface has a non-manifold edge (" << mesh.Edges[e][0] << ", " << mesh.Edges[e][1]
                                                             << ") and no \"Labels\" to tell its interfaces apart.");
        return 0;
      }

  Remesher r;
  r.Eps = this->Tolerance;
  const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
  r.P.resize(static_cast<size_t>(np));
  r.M.resize(static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
  {
    r.P[v] = Vec3(mesh.Points[v].data());
    if (this->TargetSize > 0)
      r.M[v] = Mat3::Identity() / (this->TargetSize * this->TargetSize);
    else
    {
      double m[6];
      metric->GetTuple(v, m);
      r.M[v] << m[0], m[3], m[5], m[3], m[1], m[4], m[5], m[4], m[2];
      if (!r.M[v].allFinite())
      {
        vtkErrorMacro("The metric of point " << v << " is not finite.");
        return 0;
      }
    }
  }
  r.Kind = mesh.Kind;
  r.RefPoints = r.P;
  r.Cluster.resize(static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
    r.Cluster[v].assign(1,
      { static_cast<int>(v), -1, -1 }); // the interface is set below for surface vertices
  r.VAlive.assign(static_cast<size_t>(np), 1);
  r.VT.resize(static_cast<size_t>(np));
  std::map<std::pair<int, int>, int> sheetIds;
  const bool labelled = !mesh.Labels.empty();
  for (vtkIdType t = 0; t < nt; ++t)
  {
    Tri tri;
    for (int k = 0; k < 3; ++k)
      tri.V[k] = static_cast<int>(mesh.Triangles[t][k]);
    tri.Labels[0] = labelled ? mesh.Labels[t][0] : 0;
    tri.Labels[1] = labelled ? mesh.Labels[t][1] : 0;
    const std::pair<int, int> key(std::min(tri.Labels[0], tri.Labels[1]), std::max(tri.Labels[0], tri.Labels[1]));
    auto it = sheetIds.emplace(key, static_cast<int>(sheetIds.size())).first;
    tri.Sheet = it->second;
    tri.Alive = true;
    r.T.push_back(tri);
    for (int k = 0; k < 3; ++k)
      r.VT[tri.V[k]].push_back(static_cast<int>(t));
  }
  for (vtkIdType v = 0; v < np; ++v)
    if (r.Kind[v] == amSurfaceMesh::Surface && !r.VT[v].empty())
      r.Cluster[v][0].Sheet = r.T[r.VT[v][0]].Sheet;
  // The input surface of every interface: locator and the samples of the final check.
  const int nSheets = static_cast<int>(sheetIds.size());
  r.Ref.resize(static_cast<size_t>(nSheets));
  r.RefSamples.resize(static_cast<size_t>(nSheets));
  {
    std::vector<std::vector<std::array<vtkIdType, 3>>> tris(static_cast<size_t>(nSheets));
    for (const Tri& t : r.T)
      tris[t.Sheet].push_back({ t.V[0], t.V[1], t.V[2] });
    // The locators on one thread, the samples on the other.
    auto samples = [&]() {
      std::vector<std::vector<char>> seen(static_cast<size_t>(nSheets));
      // Each edge of an interface once: an edge inside one interface is flagged; a junction edge
      // (few) is looked up with its interface.
      std::vector<char> edgeSeen(mesh.Edges.size(), 0);
      std::set<std::pair<vtkIdType, int>> junctionSeen;
      for (const Tri& t : r.T)
      {
        r.RefSamples[t.Sheet].push_back((r.P[t.V[0]] + r.P[t.V[1]] + r.P[t.V[2]]) / 3.0);
        for (int k = 0; k < 3; ++k)
        {
          const vtkIdType e = mesh.FindEdge(t.V[k], t.V[(k + 1) % 3]);
          const bool first = mesh.FeatureEdge[e] ? junctionSeen.insert({ e, t.Sheet }).second : !edgeSeen[e];
          edgeSeen[e] = 1;
          if (first)
            r.RefSamples[t.Sheet].push_back(0.5 * (r.P[t.V[k]] + r.P[t.V[(k + 1) % 3]]));
        }
        auto& s = seen[t.Sheet];
        if (s.empty())
          s.assign(static_cast<size_t>(np), 0);
        for (int k = 0; k < 3; ++k)
          if (!s[t.V[k]])
          {
            s[t.V[k]] = 1;
            r.RefSamples[t.Sheet].push_back(r.P[t.V[k]]);
          }
      }
    };
    vtkSMPTools::For(0, 2, 1, [&](vtkIdType j0, vtkIdType j1) {
      for (vtkIdType j = j0; j < j1; ++j)
        if (j == 0)
          for (int s = 0; s < nSheets; ++s)
            r.Ref[s].Build(mesh.Points, tris[s]);
        else
          samples();
    });
  }
  r.InputSheets.resize(static_cast<size_t>(np));
  r.Anchor.assign(static_cast<size_t>(np), -1);
  for (vtkIdType v = 0; v < np; ++v)
    if (r.Kind[v] != amSurfaceMesh::Surface)
    {
      r.Anchor[v] = static_cast<int>(v);
      auto& sheets = r.InputSheets[v];
      for (int t : r.VT[v])
        sheets.push_back(r.T[t].Sheet);
      std::sort(sheets.begin(), sheets.end());
      sheets.erase(std::unique(sheets.begin(), sheets.end()), sheets.end());
    }
  r.CurveNeighbours.resize(static_cast<size_t>(np));
  for (size_t e = 0; e < mesh.Edges.size(); ++e)
    if (mesh.FeatureEdge[e])
    {
      const int a = static_cast<int>(mesh.Edges[e][0]), b = static_cast<int>(mesh.Edges[e][1]);
      const double l = (r.P[a] - r.P[b]).norm();
      r.CurveNeighbours[a].push_back({ b, l });
      r.CurveNeighbours[b].push_back({ a, l });
    }
  this->UpdateProgress(0.05);

  for (int it = 0; it < this->NumberOfIterations; ++it)
  {
    r.RebuildBins();
    for (int pass = 0; pass < 8; ++pass)
    {
      if (pass > 0)
        r.RebuildBinsIfStale();
      if (r.CollapsePass() == 0)
        break;
    }
    for (int pass = 0; pass < 3; ++pass)
      if (r.FlipPass(pass > 0) == 0)
        break;
    r.RelaxPass();
    this->UpdateProgress(0.05 + 0.75 * (it + 1) / this->NumberOfIterations);
  }
  r.FlipPass();
  // The guarantee: measure, insert where the bound is exceeded, measure again.
  double upper = 0;
  vtkIdType inserted = 0;
  auto enforce = [&r, &upper, &inserted]() {
    std::vector<std::pair<int, Vec3>> insert;
    std::vector<int> edgeOf;
    double h = r.Measure(upper, insert, edgeOf);
    r.RebuildBins();
    for (int round = 0; round < 30 && !insert.empty(); ++round)
    {
      vtkIdType done = 0;
      std::vector<int> blocked;
      for (size_t i = 0; i < insert.size(); ++i)
      {
        const int t = insert[i].first;
        // Longest-edge bisection towards the input first (it keeps the angles: the far point
        // itself, inserted, often lands near a corner or an edge and leaves slivers), the far
        // point itself where the bisection is refused (its edge split there when it lies on
        // one, else or where that is refused inserted, or a vertex moved onto it).
        const bool ok = r.Refine(t) > 0 || (edgeOf[i] >= 0 && r.SplitEdge(t, edgeOf[i], insert[i].second)) ||
          r.Insert(t, insert[i].second) || r.MoveVertexNearest(t, insert[i].second);
        done += ok;
        if (!ok)
        {
          blocked.push_back(insert[i].first);
          blocked.push_back(r.W().LastHit);
        }
      }
      // Refused where a triangle is in the way (or the new ones would fold): refine both,
      // towards the input where nothing crosses.
      for (int t : blocked)
        done += r.Refine(t);
      inserted += done;
      h = r.Measure(upper, insert, edgeOf);
      if (done == 0)
        break;
    }
    return h;
  };
  double h = enforce();
  this->UpdateProgress(0.85);
  // Triangles with small angles that the insertions left (no tetrahedron on them can be good):
  // removed where a flip or collapse allows it, then the bound enforced again. Kept only if the
  // distance ends no worse than before (or within the tolerance), fewer triangles have small
  // angles and no edge got much shorter (where the bound cannot be met, more insertion rounds
  // would only refine towards a point).
  for (int attempt = 0; attempt < 3; ++attempt)
  {
    long long smallBefore, smallAfter;
    double shortestBefore, shortestAfter;
    r.AngleSummary(smallBefore, shortestBefore);
    if (smallBefore == 0)
      break; // nothing to clean: no copy of the remesher for an undo
    Remesher before = r.Snapshot();
    const double hBefore = h, upperBefore = upper;
    const vtkIdType insertedBefore = inserted;
    int cleaned = 0;
    for (int round = 0; round < 3; ++round)
    {
      const int n = r.SmallAngleCleanup();
      cleaned += n;
      if (n == 0)
        break;
    }
    if (cleaned == 0)
      break;
    h = enforce();
    r.AngleSummary(smallAfter, shortestAfter);
    if (h > std::max(hBefore, this->Tolerance) || smallAfter >= smallBefore || shortestAfter < 0.5 * shortestBefore)
    {
      r.Restore(std::move(before));
      h = hBefore;
      upper = upperBefore;
      inserted = insertedBefore;
      break;
    }
  }
  this->Hausdorff = h;
  this->HausdorffUpperBound = upper;
  this->InsertedPoints = inserted;
  if (h > this->Tolerance)
    vtkWarningMacro("The Hausdorff distance to the input is " << h << " mm, above the tolerance "
                                                              << this->Tolerance
                                                              << " mm: refining further would make triangles cross "
                                                                 "(near junction curves or thin parts of the input).");
  this->UpdateProgress(0.95);

  // Output: live vertices and triangles, labels and orientation kept.
  std::vector<vtkIdType> newId(r.P.size(), -1);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (size_t v = 0; v < r.P.size(); ++v)
    if (r.VAlive[v] && !r.VT[v].empty())
    {
      newId[v] = points->InsertNextPoint(r.P[v].data());
    }
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfComponents(2);
  for (const Tri& t : r.T)
    if (t.Alive)
    {
      const vtkIdType ids[3] = { newId[t.V[0]], newId[t.V[1]], newId[t.V[2]] };
      polys->InsertNextCell(3, ids);
      labels->InsertNextTypedTuple(t.Labels);
    }
  output->SetPoints(points);
  output->SetPolys(polys);
  if (labelled)
    output->GetCellData()->AddArray(labels);
  output->GetFieldData()->PassData(input->GetFieldData());
  for (const auto& f : { std::make_pair("Hausdorff", h), std::make_pair("HausdorffUpperBound", upper) })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(f.first);
    a->InsertNextValue(f.second);
    output->GetFieldData()->AddArray(a);
  }
  std::ostringstream params;
  params << "Tolerance=" << this->Tolerance << " TargetSize=" << this->TargetSize
         << " NumberOfIterations=" << this->NumberOfIterations << " Hausdorff=" << h
         << " InsertedPoints=" << inserted << " Collapses=" << r.Workers[0].Collapses + r.Workers[1].Collapses << " Flips=" << r.Workers[0].Flips + r.Workers[1].Flips
         << " Moves=" << r.Workers[0].Moves + r.Workers[1].Moves;
  amProvenance::Record(output, input, "amMetricRemeshing", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amMetricRemeshing::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "TargetSize: " << this->TargetSize << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
}
