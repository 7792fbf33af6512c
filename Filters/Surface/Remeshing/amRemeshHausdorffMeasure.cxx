#include "amRemeshHausdorffMeasure.h"

#include "amRemeshNearCells.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <limits>

namespace amRemesh
{
bool HausdorffMeasure::Unchanged(const Surface& S, size_t t) const
{
  const MeasureCache& c = this->Cache;
  if (!c.Valid || t >= c.Tri.size() || !S.T[t].Alive || c.Tri[t][3] != S.T[t].Sheet)
    return false;
  for (int k = 0; k < 3; ++k)
  {
    const int v = S.T[t].V[k];
    if (v != c.Tri[t][k] || static_cast<size_t>(v) >= c.P.size() || !(S.P[v] == c.P[v]))
      return false;
  }
  return true;
}

double HausdorffMeasure::ToBothRegions(
  const Surface& S, const std::vector<std::array<double, 3>>& pts, const amRemesh::Input& In, int sheet, const Vec3& x)
{
  if (this->RegionTriangles.empty())
    for (const Triangle& t : S.T) // every region's boundary in one pass, the first time one is needed
      if (t.Alive)
        for (int label : t.Labels)
          this->RegionTriangles[label].push_back({ t.V[0], t.V[1], t.V[2] });
  double farthest = 0;
  for (int label : In.SheetLabels[sheet])
  {
    auto it = this->Regions.find(label);
    if (it == this->Regions.end())
    {
      it = this->Regions.emplace(label, amTriangleLocator()).first;
      it->second.Build(pts, this->RegionTriangles[label]);
    }
    double cl[3];
    vtkIdType t;
    const double d2 = it->second.ClosestPoint(x.data(), cl, t);
    farthest = std::max(farthest, t < 0 ? std::numeric_limits<double>::infinity() : d2);
  }
  return farthest;
}

namespace
{
/// Per sheet: locators of the whole current surface (only where a sample's nearest triangle
/// changed, or at the first measure) and of the triangles changed since the last measure, with
/// the cells near those; the triangles' slots beside each locator's numbering.
struct SheetLocators
{
  std::vector<amTriangleLocator> Current, Changed;
  std::vector<NearCells> ChangedNear;
  std::vector<std::vector<int>> Ids, ChangedIds;
  std::vector<char> Whole;

  void Build(const Surface& S, const amRemesh::Input& In, const std::vector<char>& same,
    const std::vector<std::array<double, 3>>& pts, bool valid, const std::vector<std::vector<double>>& d2,
    const std::vector<std::vector<int>>& at)
  {
    const size_t nSheets = In.Ref.size(), nt = S.T.size();
    this->Current.resize(nSheets);
    this->Changed.resize(nSheets);
    this->ChangedNear.resize(nSheets);
    this->Ids.resize(nSheets);
    this->ChangedIds.resize(nSheets);
    this->Whole.assign(nSheets, 0);
    std::vector<std::vector<std::array<vtkIdType, 3>>> tris(nSheets), changedTris(nSheets);
    for (size_t t = 0; t < nt; ++t)
      if (S.T[t].Alive)
      {
        const std::array<vtkIdType, 3> v = { S.T[t].V[0], S.T[t].V[1], S.T[t].V[2] };
        tris[S.T[t].Sheet].push_back(v);
        this->Ids[S.T[t].Sheet].push_back(static_cast<int>(t));
        if (!same[t])
        {
          changedTris[S.T[t].Sheet].push_back(v);
          this->ChangedIds[S.T[t].Sheet].push_back(static_cast<int>(t));
        }
      }
    // A sheet's whole surface is searched only for the samples whose nearest triangle changed
    // (all of them at the first Measure): most later measures change a few sheets of thousands.
    vtkSMPTools::For(0, static_cast<vtkIdType>(nSheets), [&](vtkIdType s0, vtkIdType s1) {
      for (vtkIdType s = s0; s < s1; ++s)
      {
        // D2 and At are sized together: a sheet with distances known has its nearest triangles.
        if (!valid || d2.size() <= static_cast<size_t>(s) || d2[s].size() != In.Samples[s].size())
        {
          this->Whole[s] = 1;
          continue;
        }
        for (int a : at[s])
          if (a < 0 || static_cast<size_t>(a) >= nt || !same[a])
          {
            this->Whole[s] = 1;
            break;
          }
      }
    });
    vtkSMPTools::For(0, static_cast<vtkIdType>(nSheets), [&](vtkIdType s0, vtkIdType s1) {
      for (vtkIdType s = s0; s < s1; ++s)
      {
        if (this->Whole[s])
          this->Current[s].Build(pts, tris[s]);
        if (valid && !changedTris[s].empty())
        {
          this->Changed[s].Build(pts, changedTris[s]);
          this->ChangedNear[s].Build(In.Samples[s], 2.0 * In.Eps, pts, changedTris[s]);
        }
      }
    });
  }
};

/// Remeshed -> input on one triangle: a grid of points on it, spacing at most Eps; its largest
/// distance, the input point to insert for it (on the side of the input it faces), the edge its
/// farthest sample lies on (-1: inside) and the sampling gap.
void MeasureTriangle(const Surface& S, const amRemesh::Input& In, int slot, double near2, double& worst, Vec3& farPoint,
  int& farEdge, double& gap)
{
  double cl[3];
  vtkIdType tt;
  const Triangle& t = S.T[slot];
  const Vec3 &a = S.P[t.V[0]], &b = S.P[t.V[1]], &c = S.P[t.V[2]];
  const double longest = std::max({ (b - a).norm(), (c - b).norm(), (a - c).norm() });
  // Spacing Eps, at most 12 intervals per edge (the gap enters the upper bound).
  const int n = std::min(12, std::max(2, static_cast<int>(std::ceil(longest / In.Eps))));
  double w = 0;
  Vec3 far = a, farSample = a;
  int onEdge = -1;
  vtkIdType hint = -1; // the input triangle the last sample found near
  auto visit = [&](const Vec3& x, int edge) {
    // Only a sample farther than the farthest so far changes anything: the cheap test first.
    if (w > 0 && In.Ref[t.Sheet].WithinDistance(x.data(), w, nullptr, &hint))
      return;
    double d = In.Ref[t.Sheet].ClosestPointWithin(x.data(), near2, cl, tt);
    if (tt < 0)
      d = In.Ref[t.Sheet].ClosestPoint(x.data(), cl, tt);
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
  if (w > In.Eps * In.Eps)
  {
    const Vec3 normal = (b - a).cross(c - a);
    if (In.Ref[t.Sheet].ClosestPointFacing(farSample.data(), normal.data(), cl, tt) <
      std::numeric_limits<double>::infinity())
      far = Vec3(cl);
  }
  worst = std::sqrt(w);
  farPoint = far;
  farEdge = onEdge;
  gap = longest / n / std::sqrt(3.0);
}
}

double HausdorffMeasure::Measure(const Surface& S, const amRemesh::Input& In, double& upperBound,
  std::vector<std::pair<int, Vec3>>& insert, std::vector<int>& edgeOf)
{
  edgeOf.clear();
  // The regions' boundaries of this state of the surface, built on demand.
  this->Regions.clear();
  this->RegionTriangles.clear();
  const int nSheets = static_cast<int>(In.Ref.size());
  const size_t nt = S.T.size();
  std::vector<char> same(nt, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(nt), [&](vtkIdType t0, vtkIdType t1) {
    for (vtkIdType t = t0; t < t1; ++t)
      same[t] = this->Unchanged(S, static_cast<size_t>(t)) ? 1 : 0;
  });
  // Per sheet: the whole current surface, and the triangles changed since the last Measure.
  std::vector<std::array<double, 3>> pts(S.P.size());
  for (size_t i = 0; i < S.P.size(); ++i)
    pts[i] = { S.P[i].x(), S.P[i].y(), S.P[i].z() };
  SheetLocators L;
  L.Build(S, In, same, pts, this->Cache.Valid, this->Cache.D2, this->Cache.At);
  auto &cur = L.Current, &changed = L.Changed;
  auto& changedNear = L.ChangedNear;
  auto &ids = L.Ids, &changedIds = L.ChangedIds;
  auto& whole = L.Whole;
  MeasureCache& cache = this->Cache;
  cache.D2.resize(static_cast<size_t>(nSheets));
  cache.At.resize(static_cast<size_t>(nSheets));
  double worst = 0, gap = 0;
  insert.clear();
  std::vector<char> used(nt, 0);
  this->Local.assign(nt, 0.0);
  const double eps2 = In.Eps * In.Eps, near2 = 16.0 * eps2;
  // Input -> remeshed.
  for (int s = 0; s < nSheets; ++s)
  {
    const auto& samples = In.Samples[s];
    std::vector<double>& d2 = cache.D2[s];
    std::vector<int>& at = cache.At[s];
    const bool known = cache.Valid && d2.size() == samples.size();
    if (!known)
    {
      d2.assign(samples.size(), 0.0);
      at.assign(samples.size(), -1);
    }
    // Nothing of this sheet changed, and no sample's nearest triangle: every distance stays.
    const bool keep = known && !whole[s] && changedIds[s].empty();
    vtkSMPTools::For(0, keep ? 0 : static_cast<vtkIdType>(samples.size()), [&](vtkIdType i0, vtkIdType i1) {
      double cl[3];
      vtkIdType a;
      for (vtkIdType i = i0; i < i1; ++i)
        // A slot beyond the surface's: the surface was restored to an earlier, smaller state.
        if (known && at[i] >= 0 && static_cast<size_t>(at[i]) < nt && same[at[i]])
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
      // Farther than Eps from its interface: a sample within Eps of both its regions'
      // boundaries is where the interface narrowed to a junction curve (a strip between two
      // curves that a junction point's collapse closed): the regions still meet there.
      const double relaxed = d2[i] > eps2 ? this->ToBothRegions(S, pts, In, s, samples[i]) : d2[i];
      const double d = std::sqrt(std::min(d2[i], relaxed));
      worst = std::max(worst, d);
      if (at[i] >= 0 && static_cast<size_t>(at[i]) < nt)
        this->Local[at[i]] = std::max(this->Local[at[i]], d);
      if (relaxed > eps2 && at[i] >= 0)
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
    if (S.T[t].Alive)
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
    for (vtkIdType i = i0; i < i1; ++i)
    {
      MeasureTriangle(
        S, In, todo[i], near2, cache.Worst[todo[i]], cache.Far[todo[i]], cache.Edge[todo[i]], cache.Gap[todo[i]]);
    }
  });
  for (int t : alive)
  {
    worst = std::max(worst, cache.Worst[t]);
    gap = std::max(gap, cache.Gap[t]);
    this->Local[t] = std::max(this->Local[t], cache.Worst[t]);
    if (cache.Worst[t] > In.Eps && !used[t])
    {
      used[t] = 1;
      insert.push_back({ t, cache.Far[t] });
      edgeOf.push_back(cache.Edge[t]);
    }
  }
  // What this Measure saw.
  cache.Tri.resize(nt);
  for (size_t t = 0; t < nt; ++t)
    cache.Tri[t] = { S.T[t].V[0], S.T[t].V[1], S.T[t].V[2], S.T[t].Alive ? S.T[t].Sheet : -1 };
  cache.P = S.P;
  cache.Valid = true;
  upperBound = worst + gap;
  return worst;
}
}
