#include "amRemeshCrossingGuard.h"

#include "amSelfIntersection.h"

#include <cmath>

namespace amRemesh
{
bool CrossingGuard::Separated(const Vec3* p, const int* ip, const Vec3* q, const int* iq)
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

bool CrossingGuard::PairCrosses(
  const std::array<int, 3>& ia, const std::array<Vec3, 3>& pa, const std::array<int, 3>& ib, const Vec3* pb)
{
  const double* a[3] = { pa[0].data(), pa[1].data(), pa[2].data() };
  const double* b[3] = { pb[0].data(), pb[1].data(), pb[2].data() };
  const vtkIdType va[3] = { ia[0], ia[1], ia[2] }, vb[3] = { ib[0], ib[1], ib[2] };
  // Two triangles on one edge at a dihedral angle under ~1 degree: a fold.
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
}

namespace
{
/// A swept tetrahedron prepared for inclusion tests: its box, and the rows of its inverse (the
/// barycentric coordinates of x are (x - O) . R[k]); a flat one has no inside.
struct SweptTetrahedron
{
  Vec3 O, R[3], Lo, Hi;
  bool Flat;
  explicit SweptTetrahedron(const std::array<Vec3, 4>& t)
    : O(t[0])
    , Lo(t[0])
    , Hi(t[0])
  {
    const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0], e3 = t[3] - t[0];
    const double six = e1.dot(e2.cross(e3));
    const double scale = e1.squaredNorm() * e1.norm() + e2.squaredNorm() * e2.norm() + e3.squaredNorm() * e3.norm();
    this->Flat = !(std::fabs(six) > 1e-9 * scale);
    this->R[0] = e2.cross(e3) / six;
    this->R[1] = e3.cross(e1) / six;
    this->R[2] = e1.cross(e2) / six;
    for (const Vec3& x : t)
    {
      this->Lo = this->Lo.cwiseMin(x);
      this->Hi = this->Hi.cwiseMax(x);
    }
  }
  /// Each barycentric coordinate strictly positive by a margin far above rounding.
  bool StrictlyInside(const Vec3& x) const
  {
    if (this->Flat || (x.array() < this->Lo.array()).any() || (x.array() > this->Hi.array()).any())
      return false;
    const Vec3 d = x - this->O;
    const double l1 = d.dot(this->R[0]), l2 = d.dot(this->R[1]), l3 = d.dot(this->R[2]);
    constexpr double margin = 1e-7;
    return l1 > margin && l2 > margin && l3 > margin && 1.0 - l1 - l2 - l3 > margin;
  }
};
}

bool CrossingGuard::StrictlyInside(const std::array<Vec3, 4>& t, const Vec3& x)
{
  return SweptTetrahedron(t).StrictlyInside(x);
}

bool CrossingGuard::Crosses(const std::vector<std::array<int, 3>>& ids, const std::vector<std::array<Vec3, 3>>& pos,
  const std::vector<int>& removed, Worker& worker, const std::vector<std::array<Vec3, 4>>* swept) const
{
  const Surface& S = this->S;
  if (worker.Stamp.size() < S.T.size())
    worker.Stamp.resize(S.T.size() * 2, 0);
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
      if (PairCrosses(ids[n], pos[n], ids[m], pos[m].data()))
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
  if (swept)
    for (const auto& t : *swept)
      for (const Vec3& x : t)
      {
        lo = lo.cwiseMin(x);
        hi = hi.cwiseMax(x);
      }
  // The live triangles near the new ones, each once (the removed ones are stamped first), then
  // every pair whose boxes overlap tested exactly.
  const int stamp = ++worker.StampValue;
  for (int t : removed)
    worker.Stamp[t] = stamp;
  auto& near = worker.Near;
  near.clear();
  this->B.ForBins(lo, hi, [&](long long key, int zone) {
    const std::vector<int>* list = this->B.Map[zone].Find(key);
    if (!list)
      return;
    for (int t : *list)
    {
      const std::array<float, 6>& b = this->B.BinnedBox[t];
      if (b[0] > hi[0] || b[1] > hi[1] || b[2] > hi[2] || b[3] < lo[0] || b[4] < lo[1] || b[5] < lo[2] ||
        worker.Stamp[t] == stamp)
        continue;
      worker.Stamp[t] = stamp;
      if (!S.T[t].Alive)
        continue;
      NearTriangle c;
      c.Id = t;
      for (int k = 0; k < 3; ++k)
      {
        c.V[k] = S.T[t].V[k];
        c.X[k] = S.P[c.V[k]];
      }
      Bins::Box(c.X, c.Lo, c.Hi);
      if ((c.Lo.array() <= hi.array()).all() && (c.Hi.array() >= lo.array()).all())
        near.push_back(c);
    }
  });
  for (size_t n = 0; n < ids.size(); ++n)
  {
    Vec3 nlo, nhi;
    Bins::Box(pos[n].data(), nlo, nhi);
    for (const NearTriangle& c : near)
      if ((c.Lo.array() <= nhi.array()).all() && (c.Hi.array() >= nlo.array()).all() &&
        PairCrosses(ids[n], pos[n], c.V, c.X))
      {
        worker.LastHit = c.Id;
        return true;
      }
  }
  if (swept)
    for (const auto& tet : *swept)
    {
      const SweptTetrahedron t(tet);
      if (t.Flat)
        continue;
      for (const NearTriangle& c : near)
      {
        if (!((c.Lo.array() <= t.Hi.array()).all() && (c.Hi.array() >= t.Lo.array()).all()))
          continue;
        if (t.StrictlyInside(c.X[0]) || t.StrictlyInside(c.X[1]) || t.StrictlyInside(c.X[2]) ||
          t.StrictlyInside((c.X[0] + c.X[1] + c.X[2]) / 3.0))
        {
          worker.LastHit = c.Id;
          return true;
        }
      }
    }
  return false;
}
}
