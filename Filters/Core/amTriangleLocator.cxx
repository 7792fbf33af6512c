#include "amTriangleLocator.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

void amTriangleLocator::Build(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  const vtkIdType nt = static_cast<vtkIdType>(triangles.size());
  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  double edgeSum = 0;
  for (const auto& t : triangles)
  {
    for (vtkIdType v : t)
      for (int d = 0; d < 3; ++d)
      {
        lo[d] = std::min(lo[d], points[v][d]);
        hi[d] = std::max(hi[d], points[v][d]);
      }
    const auto &p = points[t[0]], &q = points[t[1]];
    edgeSum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
  if (nt == 0)
  {
    this->Triangles.clear();
    this->N[0] = this->N[1] = this->N[2] = 0;
    return;
  }
  // Bins about one mean edge wide, at most ~4 bins per triangle overall.
  double h = 1.0 * edgeSum / nt;
  const double volume = std::max(hi[0] - lo[0], 1e-9) * std::max(hi[1] - lo[1], 1e-9) * std::max(hi[2] - lo[2], 1e-9);
  h = std::max(h, std::cbrt(volume / (4.0 * nt + 1.0)));
  if (!(h > 0))
    h = 1.0;
  this->H = h;
  for (int d = 0; d < 3; ++d)
  {
    this->Origin[d] = lo[d] - 1e-6 * h;
    this->N[d] = std::max(1, static_cast<int>(std::floor((hi[d] - this->Origin[d]) / h)) + 1);
  }
  const vtkIdType nb = static_cast<vtkIdType>(this->N[0]) * this->N[1] * this->N[2];
  // Per triangle (on the threads): its record and its range of bins (lo 0..2, hi 3..5).
  std::vector<std::array<int, 6>> range(static_cast<size_t>(nt));
  this->Triangles.resize(static_cast<size_t>(nt));
  vtkSMPTools::For(0, nt, [&](vtkIdType t0, vtkIdType t1) {
    for (vtkIdType t = t0; t < t1; ++t)
    {
      for (int d = 0; d < 3; ++d)
      {
        double mn = std::numeric_limits<double>::max(), mx = -mn;
        for (vtkIdType v : triangles[t])
        {
          mn = std::min(mn, points[v][d]);
          mx = std::max(mx, points[v][d]);
        }
        range[t][d] = std::min(this->N[d] - 1, std::max(0, static_cast<int>((mn - this->Origin[d]) / h)));
        range[t][d + 3] = std::min(this->N[d] - 1, std::max(0, static_cast<int>((mx - this->Origin[d]) / h)));
      }
      Record& r = this->Triangles[t];
      const double *a = points[triangles[t][0]].data(), *b = points[triangles[t][1]].data(),
                   *c = points[triangles[t][2]].data();
      const std::array<double, 4> sphere = BoundingSphere(a, b, c);
      std::copy(sphere.begin(), sphere.begin() + 3, r.Centre);
      r.Radius = sphere[3];
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      r.Normal[0] = u[1] * v[2] - u[2] * v[1];
      r.Normal[1] = u[2] * v[0] - u[0] * v[2];
      r.Normal[2] = u[0] * v[1] - u[1] * v[0];
      for (int d = 0; d < 3; ++d)
      {
        r.Corner[0][d] = a[d];
        r.Corner[1][d] = b[d];
        r.Corner[2][d] = c[d];
      }
    }
  });
  // Counted and filled on the threads, each for a slab of bins along z (the bins of a slab
  // are consecutive; each thread takes the triangles in order, so every bin lists them in
  // order whatever the number of threads).
  this->BinStart.assign(static_cast<size_t>(nb + 1), 0);
  const int slabs = std::min(this->N[2], std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()));
  auto forSlabs = [&](auto&& visit) {
    vtkSMPTools::For(0, slabs, 1, [&](vtkIdType s0, vtkIdType s1) {
      for (vtkIdType slab = s0; slab < s1; ++slab)
      {
        const int k0 = static_cast<int>(slab * this->N[2] / slabs),
                  k1 = static_cast<int>((slab + 1) * this->N[2] / slabs);
        for (vtkIdType t = 0; t < nt; ++t)
        {
          const std::array<int, 6>& b = range[t];
          for (int k = std::max(b[2], k0); k <= std::min(b[5], k1 - 1); ++k)
            for (int j = b[1]; j <= b[4]; ++j)
              for (int i = b[0]; i <= b[3]; ++i)
                visit((static_cast<vtkIdType>(k) * this->N[1] + j) * this->N[0] + i, t);
        }
      }
    });
  };
  forSlabs([&](vtkIdType bin, vtkIdType) { ++this->BinStart[bin + 1]; });
  for (vtkIdType b = 0; b < nb; ++b)
    this->BinStart[b + 1] += this->BinStart[b];
  this->BinTriangles.resize(static_cast<size_t>(this->BinStart.back()));
  std::vector<vtkIdType> fill(this->BinStart.begin(), this->BinStart.end() - 1);
  forSlabs([&](vtkIdType bin, vtkIdType t) { this->BinTriangles[fill[bin]++] = t; });
}

std::array<double, 4> amTriangleLocator::BoundingSphere(const double a[3], const double b[3], const double c[3])
{
  std::array<double, 4> s;
  for (int d = 0; d < 3; ++d)
    s[d] = (a[d] + b[d] + c[d]) / 3.0;
  double r2 = 0;
  for (const double* p : { a, b, c })
    r2 = std::max(r2, (p[0] - s[0]) * (p[0] - s[0]) + (p[1] - s[1]) * (p[1] - s[1]) + (p[2] - s[2]) * (p[2] - s[2]));
  s[3] = std::sqrt(r2) * (1.0 + 1e-9) + 1e-12;
  return s;
}

bool amTriangleLocator::SphereBeyond(const Record& t, const double x[3], double r) const
{
  const double dx = x[0] - t.Centre[0], dy = x[1] - t.Centre[1], dz = x[2] - t.Centre[2];
  const double reach = t.Radius + r;
  return dx * dx + dy * dy + dz * dz > reach * reach;
}

double amTriangleLocator::ClosestPointOn(const double x[3], const Record& t, double closest[3])
{
  return ClosestPointOnTriangle(x, t.Corner[0], t.Corner[1], t.Corner[2], closest);
}

double amTriangleLocator::ClosestPointOnTriangle(
  const double p[3], const double a[3], const double b[3], const double c[3], double out[3])
{
  // Ericson, Real-Time Collision Detection, 5.1.5: Voronoi regions of the triangle.
  double ab[3], ac[3], ap[3];
  for (int d = 0; d < 3; ++d)
  {
    ab[d] = b[d] - a[d];
    ac[d] = c[d] - a[d];
    ap[d] = p[d] - a[d];
  }
  auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  auto set = [&](double u, double v, double w) {
    for (int d = 0; d < 3; ++d)
      out[d] = u * a[d] + v * b[d] + w * c[d];
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
    set(1, 0, 0);
  else
  {
    double bp[3], cp[3];
    for (int d = 0; d < 3; ++d)
    {
      bp[d] = p[d] - b[d];
      cp[d] = p[d] - c[d];
    }
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d3 >= 0 && d4 <= d3)
      set(0, 1, 0);
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
      const double v = d1 / (d1 - d3);
      set(1 - v, v, 0);
    }
    else if (d6 >= 0 && d5 <= d6)
      set(0, 0, 1);
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
      const double w = d2 / (d2 - d6);
      set(1 - w, 0, w);
    }
    else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
      const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
      set(0, 1 - w, w);
    }
    else
    {
      const double denom = 1.0 / (va + vb + vc);
      const double v = vb * denom, w = vc * denom;
      set(1 - v - w, v, w);
    }
  }
  double d2s = 0;
  for (int d = 0; d < 3; ++d)
    d2s += (p[d] - out[d]) * (p[d] - out[d]);
  return d2s;
}

double amTriangleLocator::ClosestPoint(const double x[3], double closest[3], vtkIdType& triangle) const
{
  return this->Closest(x, nullptr, closest, triangle);
}

double amTriangleLocator::ClosestPointFacing(
  const double x[3], const double normal[3], double closest[3], vtkIdType& triangle) const
{
  return this->Closest(x, normal, closest, triangle);
}

double amTriangleLocator::ClosestPointWithin(
  const double x[3], double bound2, double closest[3], vtkIdType& triangle) const
{
  return this->Closest(x, nullptr, closest, triangle, bound2);
}

double amTriangleLocator::Closest(
  const double x[3], const double* normal, double closest[3], vtkIdType& triangle, double bound2) const
{
  triangle = -1;
  double best = bound2;
  if (this->Triangles.empty())
    return best;
  int c[3];
  for (int d = 0; d < 3; ++d)
    c[d] = std::min(this->N[d] - 1, std::max(0, static_cast<int>(std::floor((x[d] - this->Origin[d]) / this->H))));
  const int maxR = std::max({ c[0], this->N[0] - 1 - c[0], c[1], this->N[1] - 1 - c[1], c[2], this->N[2] - 1 - c[2] });
  double q[3];
  double reachBest = std::numeric_limits<double>::infinity(); // sqrt(best)
  if (best < std::numeric_limits<double>::infinity())
    reachBest = std::sqrt(best);
  for (int r = 0; r <= maxR; ++r)
  {
    for (int k = c[2] - r; k <= c[2] + r; ++k)
    {
      if (k < 0 || k >= this->N[2])
        continue;
      for (int j = c[1] - r; j <= c[1] + r; ++j)
      {
        if (j < 0 || j >= this->N[1])
          continue;
        const bool shellJK = std::abs(k - c[2]) == r || std::abs(j - c[1]) == r;
        for (int i = c[0] - r; i <= c[0] + r; i += (shellJK || r == 0) ? 1 : 2 * r)
        {
          if (i < 0 || i >= this->N[0])
            continue;
          // Skip a bin that cannot hold anything closer than the best so far.
          const int bi[3] = { i, j, k };
          double boxD2 = 0;
          for (int d = 0; d < 3; ++d)
          {
            const double lo = this->Origin[d] + bi[d] * this->H, hi = lo + this->H;
            const double g = x[d] < lo ? lo - x[d] : (x[d] > hi ? x[d] - hi : 0.0);
            boxD2 += g * g;
          }
          if (boxD2 >= best)
            continue;
          const vtkIdType b = (static_cast<vtkIdType>(k) * this->N[1] + j) * this->N[0] + i;
          for (vtkIdType s = this->BinStart[b]; s < this->BinStart[b + 1]; ++s)
          {
            const vtkIdType t = this->BinTriangles[s];
            const Record& tri = this->Triangles[t];
            if (reachBest < std::numeric_limits<double>::infinity() && this->SphereBeyond(tri, x, reachBest))
              continue; // no point of this triangle can be closer than the best so far
            if (normal && !Faces(tri, normal))
              continue; // facing the other way: the other side of a thin part
            if (best < std::numeric_limits<double>::infinity() && PlaneBeyond(tri, x, best))
              continue; // its plane is farther than the best so far
            const double d2 = ClosestPointOn(x, tri, q);
            if (d2 < best)
            {
              best = d2;
              reachBest = std::sqrt(best);
              triangle = t;
              closest[0] = q[0];
              closest[1] = q[1];
              closest[2] = q[2];
            }
          }
        }
      }
    }
    // Everything not yet searched lies in the grid outside the box of bins c-r .. c+r: in six
    // slabs of the grid, before and after that box along each axis. The nearest of them bounds
    // what is left (also for a point outside the grid, whose bin c is clamped: there the
    // distance across the grid's own faces counts too).
    double reach2 = std::numeric_limits<double>::infinity();
    for (int d = 0; d < 3; ++d)
      for (int side = 0; side < 2; ++side)
      {
        if (side == 0 ? c[d] - r <= 0 : c[d] + r >= this->N[d] - 1)
          continue; // nothing left on that side
        double g2 = 0;
        for (int e = 0; e < 3; ++e)
        {
          double lo = this->Origin[e], hi = this->Origin[e] + this->N[e] * this->H;
          if (e == d)
            (side == 0 ? hi : lo) = this->Origin[d] + (side == 0 ? c[d] - r : c[d] + r + 1) * this->H;
          const double g = x[e] < lo ? lo - x[e] : (x[e] > hi ? x[e] - hi : 0.0);
          g2 += g * g;
        }
        reach2 = std::min(reach2, g2);
      }
    if (reach2 == std::numeric_limits<double>::infinity())
      break; // the whole grid is searched
    if (best <= reach2)
      break;
  }
  return best;
}

bool amTriangleLocator::WithinDistance(const double x[3], double r2, const double* normal, vtkIdType* hint) const
{
  if (this->Triangles.empty() || !(r2 >= 0))
    return false;
  double q[3];
  if (hint && *hint >= 0 && *hint < static_cast<vtkIdType>(this->Triangles.size()))
  {
    const Record& tri = this->Triangles[*hint];
    if ((!normal || Faces(tri, normal)) && ClosestPointOn(x, tri, q) <= r2)
      return true;
  }
  const double r = std::sqrt(r2);
  int b0[3], b1[3], c[3];
  for (int d = 0; d < 3; ++d)
  {
    b0[d] = std::max(0, static_cast<int>(std::floor((x[d] - r - this->Origin[d]) / this->H)));
    b1[d] = std::min(this->N[d] - 1, static_cast<int>(std::floor((x[d] + r - this->Origin[d]) / this->H)));
    if (b0[d] > b1[d])
      return false;
    c[d] = std::min(b1[d], std::max(b0[d], static_cast<int>(std::floor((x[d] - this->Origin[d]) / this->H))));
  }
  auto inBin = [&](vtkIdType b) {
    for (vtkIdType s = this->BinStart[b]; s < this->BinStart[b + 1]; ++s)
    {
      const Record& tri = this->Triangles[this->BinTriangles[s]];
      if (this->SphereBeyond(tri, x, r) || (normal && !Faces(tri, normal)) || PlaneBeyond(tri, x, r2))
        continue;
      if (ClosestPointOn(x, tri, q) <= r2)
      {
        if (hint)
          *hint = this->BinTriangles[s];
        return true;
      }
    }
    return false;
  };
  // The bin holding x first: the nearest triangles are most likely there.
  const vtkIdType centre = (static_cast<vtkIdType>(c[2]) * this->N[1] + c[1]) * this->N[0] + c[0];
  if (inBin(centre))
    return true;
  for (int k = b0[2]; k <= b1[2]; ++k)
    for (int j = b0[1]; j <= b1[1]; ++j)
      for (int i = b0[0]; i <= b1[0]; ++i)
      {
        const vtkIdType b = (static_cast<vtkIdType>(k) * this->N[1] + j) * this->N[0] + i;
        if (b != centre && inBin(b))
          return true;
      }
  return false;
}
