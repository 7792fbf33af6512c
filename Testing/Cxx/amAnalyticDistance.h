// Distance between a labelled surface and the analytic interfaces of the thorax phantom (tests and
// benchmarks): the truth is amThoraxPhantomModel::LabelAt, a pure function of position.
#ifndef amAnalyticDistance_h
#define amAnalyticDistance_h

#include "amThoraxPhantomModel.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace amTest
{
struct AnalyticDistance
{
  double SurfaceToTruth = 0; // largest, over the surface's vertices and triangle centres
  double TruthToSurface = 0; // largest, over interface points of the analytic model
  double MeanSurfaceToTruth = 0;
  long long TruthSamples = 0;
  std::vector<double> Distances; // surface -> truth, per sample point
  double Hausdorff() const { return std::max(this->SurfaceToTruth, this->TruthToSurface); }
  /// Fraction of the surface's sample points within 'limit' of the truth.
  double FractionWithin(double limit) const
  {
    const auto n = std::count_if(this->Distances.begin(), this->Distances.end(), [=](double d) { return d <= limit; });
    return this->Distances.empty() ? 1.0 : static_cast<double>(n) / this->Distances.size();
  }
};

/// Two-sided distance between surface s (cell data "Labels": the two labels of each triangle)
/// and the phantom's analytic interfaces (truth -> surface only when s has no "Labels").
/// Surface -> truth: from each vertex and triangle centre q of a triangle separating labels a and
/// b, the nearest points with label a and with label b are sought along the triangle's normal
/// (steps of 'resolution' mm, up to 'reach'); the interface between them is at most the farther of
/// the two away, which is the distance counted (an upper bound).
/// Truth -> surface: the model is sampled on a grid of 'step' mm over the surface's bounds; where two
/// neighbouring samples differ, the interface point between them (bisection to 1e-4 mm) is
/// measured to the closest point of the surface.
inline AnalyticDistance DistanceToPhantom(
  vtkPolyData* s, double step = 2.0, double resolution = 0.05, double reach = 4.0)
{
  const amThoraxPhantomModel model;
  AnalyticDistance r;
  vtkDataArray* labels = s->GetCellData()->GetArray("Labels");
  double total = 0;
  long long count = 0;
  vtkIdType npts;
  const vtkIdType* ids;
  // Without "Labels" (e.g. vtkQuadricDecimation's output) only truth -> surface is measured.
  for (vtkIdType t = 0; labels && t < s->GetNumberOfCells(); ++t)
  {
    s->GetCellPoints(t, npts, ids);
    if (npts != 3)
      continue;
    const int a = static_cast<int>(labels->GetComponent(t, 0)), b = static_cast<int>(labels->GetComponent(t, 1));
    double p[4][3], u[3], v[3], n[3];
    for (int k = 0; k < 3; ++k)
      s->GetPoint(ids[k], p[k]);
    for (int d = 0; d < 3; ++d)
      p[3][d] = (p[0][d] + p[1][d] + p[2][d]) / 3.0;
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, n);
    if (vtkMath::Normalize(n) == 0.0)
      continue;
    for (const auto& q : p)
    {
      double foundA = -1, foundB = -1;
      for (double d = 0; d <= reach && (foundA < 0 || foundB < 0); d += resolution)
        for (double sign : { -1.0, 1.0 })
        {
          const double x[3] = { q[0] + sign * d * n[0], q[1] + sign * d * n[1], q[2] + sign * d * n[2] };
          const int l = model.LabelAt(x);
          if (l == a && foundA < 0)
            foundA = d;
          if (l == b && foundB < 0)
            foundB = d;
        }
      const double dist = (foundA < 0 || foundB < 0) ? reach : std::max(foundA, foundB);
      r.Distances.push_back(dist);
      r.SurfaceToTruth = std::max(r.SurfaceToTruth, dist);
      total += dist;
      ++count;
    }
  }
  r.MeanSurfaceToTruth = count ? total / count : 0.0;

  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(s);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double bounds[6];
  s->GetBounds(bounds);
  int n[3];
  for (int d = 0; d < 3; ++d)
  {
    bounds[2 * d] -= step;
    n[d] = static_cast<int>(std::ceil((bounds[2 * d + 1] + step - bounds[2 * d]) / step)) + 1;
  }
  auto at = [&](int i, int j, int k, double x[3]) {
    x[0] = bounds[0] + i * step;
    x[1] = bounds[2] + j * step;
    x[2] = bounds[4] + k * step;
    return static_cast<int>(model.LabelAt(x));
  };
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        double x[3];
        const int l = at(i, j, k, x);
        const int next[3][3] = { { i + 1, j, k }, { i, j + 1, k }, { i, j, k + 1 } };
        for (const auto& m : next)
        {
          if (m[0] >= n[0] || m[1] >= n[1] || m[2] >= n[2])
            continue;
          double y[3];
          if (at(m[0], m[1], m[2], y) == l)
            continue;
          double lo[3] = { x[0], x[1], x[2] }, hi[3] = { y[0], y[1], y[2] };
          while (std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi)) > 1e-4)
          {
            double mid[3];
            for (int d = 0; d < 3; ++d)
              mid[d] = 0.5 * (lo[d] + hi[d]);
            std::copy(mid, mid + 3, model.LabelAt(mid) == l ? lo : hi);
          }
          double closest[3], d2;
          vtkIdType cellId;
          int sub;
          locator->FindClosestPoint(lo, closest, cell, cellId, sub, d2);
          r.TruthToSurface = std::max(r.TruthToSurface, std::sqrt(d2));
          ++r.TruthSamples;
        }
      }
  return r;
}
}

#endif
