#include "amSurfaceCurvature.h"

#include "amSurfaceMesh.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace
{
using Vec3 = Eigen::Vector3d;

struct Curvature
{
  double K1 = 0, K2 = 0; // K1 >= K2 (signed)
  Vec3 D1 = Vec3::UnitX(), D2 = Vec3::UnitY(), N = Vec3::UnitZ();
};

/// Fit the height function to the neighbourhood of p in the frame of normal n.
Curvature Fit(const Vec3& p, const Vec3& n, const std::vector<Vec3>& nbrs)
{
  Curvature c;
  c.N = n;
  Vec3 t1 = (std::fabs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  Vec3 t2 = n.cross(t1);
  c.D1 = t1;
  c.D2 = t2;
  if (nbrs.size() < 5)
    return c;
  Eigen::Matrix<double, 5, 5> A = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> b = Eigen::Matrix<double, 5, 1>::Zero();
  double scale = 0;
  for (const Vec3& q : nbrs)
    scale += (q - p).squaredNorm();
  scale = std::sqrt(scale / nbrs.size()); // condition the system: unit-size coordinates
  if (!(scale > 0))
    return c;
  // The normal equations of the rows (u^2, uv, v^2, u, v) from the 12 moments they need (the
  // 5x5 outer product per point was most of this filter's time).
  double s4[5] = { 0, 0, 0, 0, 0 }, s3[4] = { 0, 0, 0, 0 }, s2[3] = { 0, 0, 0 };
  const double inverse = 1.0 / scale;
  for (const Vec3& q : nbrs)
  {
    const Vec3 d = (q - p) * inverse;
    const double u = d.dot(t1), v = d.dot(t2), w = d.dot(n);
    const double uu = u * u, uv = u * v, vv = v * v;
    s4[0] += uu * uu;
    s4[1] += uu * uv;
    s4[2] += uu * vv;
    s4[3] += uv * vv;
    s4[4] += vv * vv;
    s3[0] += uu * u;
    s3[1] += uu * v;
    s3[2] += uv * v;
    s3[3] += vv * v;
    s2[0] += uu;
    s2[1] += uv;
    s2[2] += vv;
    b(0) += uu * w;
    b(1) += uv * w;
    b(2) += vv * w;
    b(3) += u * w;
    b(4) += v * w;
  }
  A << s4[0], s4[1], s4[2], s3[0], s3[1], //
    s4[1], s4[2], s4[3], s3[1], s3[2],    //
    s4[2], s4[3], s4[4], s3[2], s3[3],    //
    s3[0], s3[1], s3[2], s2[0], s2[1],    //
    s3[1], s3[2], s3[3], s2[1], s2[2];
  Eigen::LDLT<Eigen::Matrix<double, 5, 5>> ldlt(A);
  if (ldlt.info() != Eigen::Success || std::fabs(A.determinant()) < 1e-14)
    return c;
  const Eigen::Matrix<double, 5, 1> x = ldlt.solve(b);
  // Back to mm: h(u,v) in scaled units -> second derivatives divide by scale.
  const double a = x(0) / scale, bb = x(1) / scale, cc = x(2) / scale, d = x(3), e = x(4);
  const double W = std::sqrt(1 + d * d + e * e);
  Eigen::Matrix2d I, II;
  I << 1 + d * d, d * e, d * e, 1 + e * e;
  II << 2 * a / W, bb / W, bb / W, 2 * cc / W;
  const Eigen::Matrix2d S = I.inverse() * II;
  Eigen::EigenSolver<Eigen::Matrix2d> es(S);
  const Eigen::Vector2d ev = es.eigenvalues().real();
  const Eigen::Matrix2d evec = es.eigenvectors().real();
  // Bending away from the normal is positive curvature: h = -k r^2 / 2.
  const double k0 = -ev(0), k1 = -ev(1);
  const int i1 = k0 >= k1 ? 0 : 1, i2 = 1 - i1;
  c.K1 = -ev(i1);
  c.K2 = -ev(i2);
  const Vec3 xu = t1 + d * n, xv = t2 + e * n;
  Vec3 dir = evec(0, i1) * xu + evec(1, i1) * xv;
  dir -= dir.dot(n) * n;
  if (dir.norm() > 1e-12)
  {
    c.D1 = dir.normalized();
    c.D2 = n.cross(c.D1);
  }
  return c;
}
}

namespace
{
struct Stamps
{
  std::vector<int> Of; // per vertex: the search that last reached it
  int Current = 0;
};

// Each triangle's interface (its unordered pair of labels), once: the neighbourhood searches
// compare it millions of times. A vertex whose triangles all lie on one interface (all but the
// junction curves' vertices) has it; the search steps from it to its edge neighbours, a third of
// the visits its triangles' corners take. Mixed: a vertex on two interfaces or more.
constexpr long long Mixed = std::numeric_limits<long long>::min();
void Sheets(const amSurfaceMesh& mesh, bool labelled, std::vector<long long>& sheetOfTriangle,
  std::vector<long long>& sheetOfVertex)
{
  const vtkIdType np = mesh.NumberOfPoints();
  sheetOfTriangle.assign(labelled ? mesh.Triangles.size() : 0, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(sheetOfTriangle.size()), [&](vtkIdType t0, vtkIdType t1) {
    for (vtkIdType t = t0; t < t1; ++t)
    {
      const int a = std::min(mesh.Labels[t][0], mesh.Labels[t][1]), b = std::max(mesh.Labels[t][0], mesh.Labels[t][1]);
      sheetOfTriangle[t] = (static_cast<long long>(a) << 32) ^ static_cast<unsigned int>(b);
    }
  });
  sheetOfVertex.assign(static_cast<size_t>(np), 0);
  if (labelled)
    vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
      for (vtkIdType v = v0; v < v1; ++v)
      {
        const vtkIdType r0 = mesh.VertexTriangleStart[v], r1 = mesh.VertexTriangleStart[v + 1];
        long long sheet = r1 > r0 ? sheetOfTriangle[mesh.VertexTriangles[r0]] : Mixed;
        for (vtkIdType r = r0 + 1; r < r1 && sheet != Mixed; ++r)
          if (sheetOfTriangle[mesh.VertexTriangles[r]] != sheet)
            sheet = Mixed;
        sheetOfVertex[v] = sheet;
      }
    });
}

// The size each vertex asks for taken as the median over its 2-ring (a vertex whose small fit
// was all noise does not stay at the small scale), within the first radius and three times it.
void MedianRadii(const amSurfaceMesh& mesh, const std::vector<double>& h, double baseRadius,
  vtkSMPThreadLocal<Stamps>& stampLocal, std::vector<double>& radius)
{
  const vtkIdType np = mesh.NumberOfPoints();
  vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
    Stamps& stamps = stampLocal.Local();
    std::vector<int>& stamp = stamps.Of;
    if (stamp.size() != static_cast<size_t>(np))
      stamp.assign(static_cast<size_t>(np), 0);
    std::vector<vtkIdType> near;
    std::vector<double> values;
    for (vtkIdType v = v0; v < v1; ++v)
    {
      // The 2-ring, each vertex once (the median does not depend on their order).
      const int mark = ++stamps.Current;
      near.assign(1, v);
      stamp[v] = mark;
      for (int ring = 0, from = 0; ring < 2; ++ring)
      {
        const int to = static_cast<int>(near.size());
        for (int i = from; i < to; ++i)
          for (vtkIdType r = mesh.RingStart[near[i]]; r < mesh.RingStart[near[i] + 1]; ++r)
            if (stamp[mesh.Ring[r]] != mark)
            {
              stamp[mesh.Ring[r]] = mark;
              near.push_back(mesh.Ring[r]);
            }
        from = to;
      }
      values.clear();
      for (vtkIdType q : near)
        values.push_back(h[q]);
      std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
      radius[v] = std::max(baseRadius, std::min(3.0 * baseRadius, values[values.size() / 2]));
    }
  });
}
}

double amSurfaceCurvature::Size(double k, const Settings& s)
{
  const double a = std::fabs(k);
  return a > 0 ? std::min(s.MaximumSize, std::max(s.MinimumSize, std::sqrt(6 * s.Tolerance / a))) : s.MaximumSize;
}

std::vector<amSurfaceCurvature::Principal> amSurfaceCurvature::Estimate(
  const amSurfaceMesh& mesh, const Settings& s, const std::function<void(double)>& progress)
{
  const auto report = [&progress](double f) {
    if (progress)
      progress(f);
  };
  const vtkIdType np = mesh.NumberOfPoints();
  const bool labelled = mesh.Labels.size() == mesh.Triangles.size();
  std::vector<long long> sheetOfTriangle, sheetOfVertex;
  Sheets(mesh, labelled, sheetOfTriangle, sheetOfVertex);
  auto sheetOf = [&](vtkIdType t) -> long long { return labelled ? sheetOfTriangle[t] : 0; };
  // The fit's neighbourhood: every vertex of the interface within 'radius' of the vertex (reached
  // through the interface's triangles), and at least its NeighborhoodRings-ring.
  const double baseRadius = s.Radius;
  const int rings = s.Rings;
  auto sizeOf = [&s](double k) { return amSurfaceCurvature::Size(k, s); };
  vtkSMPThreadLocal<Stamps> stampLocal;
  std::vector<Curvature> curv(static_cast<size_t>(np));
  // radius: per vertex; a vertex whose radius changed by less than 10 % since its last fit keeps it.
  std::vector<double> fitted(static_cast<size_t>(np), -1.0);
  auto fitAll = [&](const std::vector<double>& radius) {
    vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
      Stamps& stamps = stampLocal.Local();
      std::vector<int>& stamp = stamps.Of;
      if (stamp.size() != static_cast<size_t>(np))
        stamp.assign(static_cast<size_t>(np), 0);
      std::vector<vtkIdType> frontier, next, seen;
      std::vector<Vec3> nbrs;
      std::vector<long long> sheets;
      for (vtkIdType v = v0; v < v1; ++v)
      {
        if (fitted[v] >= 0 && std::fabs(radius[v] - fitted[v]) <= 0.1 * fitted[v])
          continue;
        fitted[v] = radius[v];
        sheets.clear();
        for (vtkIdType r = mesh.VertexTriangleStart[v]; r < mesh.VertexTriangleStart[v + 1]; ++r)
          sheets.push_back(sheetOf(mesh.VertexTriangles[r]));
        std::sort(sheets.begin(), sheets.end());
        sheets.erase(std::unique(sheets.begin(), sheets.end()), sheets.end());
        const Vec3 p(mesh.Points[v].data());
        const double r2 = radius[v] * radius[v];
        Curvature best;
        double bestK = -1;
        for (long long sheet : sheets)
        {
          const int mark = ++stamps.Current;
          Vec3 n = Vec3::Zero();
          for (vtkIdType r = mesh.VertexTriangleStart[v]; r < mesh.VertexTriangleStart[v + 1]; ++r)
          {
            const vtkIdType t = mesh.VertexTriangles[r];
            if (sheetOf(t) == sheet)
              n += Vec3(mesh.TriangleNormal(t).data());
          }
          if (n.norm() == 0)
            continue;
          n.normalize();
          seen.assign(1, v);
          stamp[v] = mark;
          frontier.assign(1, v);
          for (int ring = 0; !frontier.empty(); ++ring)
          {
            next.clear();
            auto visit = [&](vtkIdType q) {
              if (stamp[q] == mark || stamp[q] == -mark)
                return;
              if (ring < rings || (Vec3(mesh.Points[q].data()) - p).squaredNorm() <= r2)
              {
                stamp[q] = mark;
                seen.push_back(q);
                next.push_back(q);
              }
              else
                stamp[q] = -mark; // beyond the radius: so at every later ring too
            };
            for (vtkIdType f : frontier)
              if (sheetOfVertex[f] == sheet)
                for (vtkIdType r = mesh.RingStart[f]; r < mesh.RingStart[f + 1]; ++r)
                  visit(mesh.Ring[r]);
              else
                for (vtkIdType r = mesh.VertexTriangleStart[f]; r < mesh.VertexTriangleStart[f + 1]; ++r)
                {
                  const vtkIdType t = mesh.VertexTriangles[r];
                  if (sheetOf(t) == sheet)
                    for (vtkIdType q : mesh.Triangles[t])
                      visit(q);
                }
            frontier.swap(next);
          }
          nbrs.clear();
          for (size_t i = 1; i < seen.size(); ++i)
            nbrs.emplace_back(mesh.Points[seen[i]].data());
          const Curvature c = Fit(p, n, nbrs);
          const double k = std::max(std::fabs(c.K1), std::fabs(c.K2));
          if (k > bestK)
          {
            bestK = k;
            best = c;
          }
        }
        curv[v] = best;
      }
    });
  };
  std::vector<double> radius(static_cast<size_t>(np), baseRadius);
  fitAll(radius);
  report(0.3);
  if (s.ScaleAdaptive)
  {
    // Again at the scale of the triangles asked for: over the size the last fit gives (the disc a
    // vertex's triangles will cover; from the first radius to three times it), so that ripples
    // shorter than the triangles (the staircase that smoothing leaves on a label map's surface) average
    // out instead of shrinking every size. The size taken is the median over the vertex's 2-ring,
    // so that a vertex whose small fit was all noise does not stay at the small scale.
    std::vector<double> h(static_cast<size_t>(np));
    for (int pass = 0; pass < 3; ++pass)
    {
      for (vtkIdType v = 0; v < np; ++v)
        h[v] = std::min(sizeOf(curv[v].K1), sizeOf(curv[v].K2));
      MedianRadii(mesh, h, baseRadius, stampLocal, radius);
      fitAll(radius);
      report(0.3 + 0.1 * (pass + 1));
    }
  }
  std::vector<Principal> out(static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
  {
    out[v].K1 = curv[v].K1;
    out[v].K2 = curv[v].K2;
    for (int d = 0; d < 3; ++d)
    {
      out[v].D1[d] = curv[v].D1[d];
      out[v].D2[d] = curv[v].D2[d];
      out[v].N[d] = curv[v].N[d];
    }
  }
  return out;
}

void amSurfaceCurvature::Grade(const amSurfaceMesh& mesh, double slope, std::vector<double>& f)
{
  const vtkIdType np = mesh.NumberOfPoints();
  using Item = std::pair<double, vtkIdType>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (vtkIdType v = 0; v < np; ++v)
    queue.push({ f[v], v });
  while (!queue.empty())
  {
    const Item it = queue.top();
    queue.pop();
    if (it.first > f[it.second])
      continue;
    const vtkIdType i = it.second;
    for (vtkIdType r = mesh.RingStart[i]; r < mesh.RingStart[i + 1]; ++r)
    {
      const vtkIdType j = mesh.Ring[r];
      const double L = (Vec3(mesh.Points[i].data()) - Vec3(mesh.Points[j].data())).norm();
      const double candidate = f[i] + slope * L;
      if (candidate < f[j])
      {
        f[j] = candidate;
        queue.push({ candidate, j });
      }
    }
  }
}
