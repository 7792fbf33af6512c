// Surface benchmarks: label map -> surface (amLabelSurface against the VTK filters a user would
// otherwise pick), smoothing, curvature metric and metric remeshing (against vtkQuadricDecimation
// at the same triangle count, on accuracy and triangle quality). Phantom at 1 mm and 0.5 mm and
// the frog. Prints seconds, triangles, Hausdorff distances and the process's peak memory.
// Run: build/bin/BenchmarkSurface [--benchmark_filter=...]
#include "../Cxx/amAnalyticDistance.h"
#include "../Cxx/amSurfaceTestUtilities.h"
#include "amCurvatureMetric.h"
#include "amImageReader.h"
#include "amLabelSurface.h"
#include "amMetricRemeshing.h"
#include "amSurfaceDistance.h"
#include "amSurfaceSmoothing.h"
#include "amThoraxPhantomSource.h"

#include "amCgalIsotropicRemeshing.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkDiscreteFlyingEdges3D.h"
#include "vtkDiscreteMarchingCubes.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkQuadricDecimation.h"
#include "vtkSMPTools.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <sys/resource.h>
#include <sys/stat.h>

namespace
{
double PeakMegabytes()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

vtkImageData* Labels(int which) // 10: phantom 1 mm, 5: phantom 0.5 mm, 0: frog
{
  static std::map<int, vtkSmartPointer<vtkImageData>> cache;
  auto& img = cache[which];
  if (!img)
  {
    img = vtkSmartPointer<vtkImageData>::New();
    if (which == 0)
    {
      const std::string path = std::string(ANATOMESH_SHARED_DATA) + "/vtk_frog_tissue_labels/frogtissue.mhd";
      struct stat st;
      if (::stat(path.c_str(), &st) != 0)
        return nullptr;
      vtkNew<amImageReader> r;
      r->SetFileName(path.c_str());
      r->Update();
      img->ShallowCopy(r->GetOutput());
    }
    else
    {
      vtkNew<amThoraxPhantomSource> src;
      src->SetSpacing(which / 10.0, which / 10.0, which / 10.0);
      src->Update();
      img->ShallowCopy(src->GetOutput(1));
    }
  }
  return img;
}

int MaxLabel(vtkImageData* img)
{
  double range[2];
  img->GetScalarRange(range);
  return static_cast<int>(range[1]);
}

void Extract(benchmark::State& state)
{
  const int which = static_cast<int>(state.range(0)), method = static_cast<int>(state.range(1));
  vtkImageData* img = Labels(which);
  if (!img)
  {
    state.SkipWithError("../shared/data/vtk_frog_tissue_labels is absent");
    return;
  }
  vtkSMPTools::SetBackend("STDThread");
  vtkIdType triangles = 0;
  for (auto _ : state)
  {
    vtkSmartPointer<vtkPolyDataAlgorithm> f;
    if (method == 0)
    {
      auto ls = vtkSmartPointer<amLabelSurface>::New();
      ls->SetComputeTopology(false);
      f = ls;
    }
    else if (method == 1)
    {
      auto d = vtkSmartPointer<vtkDiscreteFlyingEdges3D>::New();
      d->GenerateValues(MaxLabel(img), 1, MaxLabel(img));
      d->ComputeNormalsOff();
      d->ComputeGradientsOff();
      d->ComputeScalarsOn();
      f = d;
    }
    else
    {
      auto d = vtkSmartPointer<vtkDiscreteMarchingCubes>::New();
      d->GenerateValues(MaxLabel(img), 1, MaxLabel(img));
      d->ComputeNormalsOff();
      d->ComputeGradientsOff();
      f = d;
    }
    f->SetInputData(img);
    f->Update();
    triangles = f->GetOutput()->GetNumberOfCells();
  }
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["peak_MB"] = PeakMegabytes();
}
// (data, method): data 10 = phantom 1 mm, 5 = phantom 0.5 mm, 0 = frog;
// method 0 = amLabelSurface, 1 = vtkDiscreteFlyingEdges3D, 2 = vtkDiscreteMarchingCubes.
BENCHMARK(Extract)->ArgsProduct({ { 10, 5, 0 }, { 0, 1, 2 } })->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

/// The smoothed 1 mm phantom surface (computed once).
vtkPolyData* Smoothed()
{
  static vtkSmartPointer<vtkPolyData> smooth;
  if (!smooth)
  {
    vtkNew<amLabelSurface> ls;
    ls->SetInputData(Labels(10));
    ls->SetComputeTopology(false);
    vtkNew<amSurfaceSmoothing> sm;
    sm->SetInputConnection(ls->GetOutputPort());
    sm->Update();
    smooth = sm->GetOutput();
  }
  return smooth;
}

/// Triangles, Hausdorff and mean distance to the reference, and the angle figures.
void SurfaceCounters(benchmark::State& state, vtkPolyData* result, vtkPolyData* reference)
{
  vtkNew<amSurfaceDistance> d;
  d->SetInputData(0, result);
  d->SetInputData(1, reference);
  d->Update();
  state.counters["input_triangles"] = static_cast<double>(reference->GetNumberOfCells());
  state.counters["triangles"] = static_cast<double>(result->GetNumberOfCells());
  state.counters["hausdorff_mm"] = d->GetHausdorff();
  state.counters["mean_mm"] = 0.5 * (d->GetMeanAToB() + d->GetMeanBToA());
  state.counters["angles_ge_20"] = amTest::AngleFraction(result, 20);
  state.counters["peak_MB"] = PeakMegabytes();
}

/// Curvature metric (isotropic) and MetricRemeshing at tolerance eps; the seconds of each step.
vtkSmartPointer<vtkPolyData> MetricRemesh(
  vtkPolyData* input, double eps, double minimumSize, double& metricSeconds, double& remeshSeconds)
{
  vtkNew<amCurvatureMetric> cm;
  cm->SetInputData(input);
  cm->SetTolerance(eps);
  cm->SetMinimumSize(minimumSize);
  cm->SetAnisotropic(false);
  auto t0 = std::chrono::steady_clock::now();
  cm->Update();
  metricSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  vtkNew<amMetricRemeshing> rm;
  rm->SetInputConnection(cm->GetOutputPort());
  rm->SetTolerance(eps);
  t0 = std::chrono::steady_clock::now();
  rm->Update();
  remeshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rm->GetOutput();
}

/// Phantom at 1 mm: smoothing, metric and remeshing (eps 0.2 mm); then vtkQuadricDecimation of
/// the smoothed surface to the same triangle count. Both measured against the smoothed surface.
void Remesh(benchmark::State& state)
{
  const bool quadric = state.range(0) == 1;
  static vtkIdType remeshedTriangles = 0;
  vtkSMPTools::SetBackend("STDThread");
  vtkPolyData* smooth = Smoothed();
  vtkSmartPointer<vtkPolyData> result;
  double secondsMetric = 0, secondsRemesh = 0;
  for (auto _ : state)
  {
    if (!quadric)
    {
      result = MetricRemesh(smooth, 0.2, 1.0, secondsMetric, secondsRemesh);
      remeshedTriangles = result->GetNumberOfCells();
    }
    else
    {
      vtkNew<vtkQuadricDecimation> q;
      q->SetInputData(smooth);
      q->SetTargetReduction(
        1.0 - static_cast<double>(remeshedTriangles ? remeshedTriangles : 227000) / smooth->GetNumberOfCells());
      q->Update();
      result = q->GetOutput();
    }
  }
  SurfaceCounters(state, result, smooth);
  state.counters["metric_s"] = secondsMetric;
  state.counters["remesh_s"] = secondsRemesh;
  // Against the phantom's analytic interfaces (the bar: within one voxel, 1 mm).
  const amTest::AnalyticDistance truth = amTest::DistanceToPhantom(result, 1.0);
  state.counters["analytic_truth_to_surface_mm"] = truth.TruthToSurface;
  state.counters["analytic_surface_mean_mm"] = truth.MeanSurfaceToTruth;
  state.counters["analytic_surface_within_1mm"] = truth.FractionWithin(1.0);
  if (!quadric)
  {
    const amTest::AnalyticDistance smoothTruth = amTest::DistanceToPhantom(smooth, 1.0);
    state.counters["smoothed_truth_to_surface_mm"] = smoothTruth.TruthToSurface;
    state.counters["smoothed_surface_mean_mm"] = smoothTruth.MeanSurfaceToTruth;
    state.counters["smoothed_surface_within_1mm"] = smoothTruth.FractionWithin(1.0);
  }
}
// 0 = amCurvatureMetric + amMetricRemeshing, 1 = vtkQuadricDecimation to the same count.
BENCHMARK(Remesh)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

/// The outer surface of the smoothed 1 mm phantom (every triangle facing the background), as one
/// unlabelled closed surface: the reference case for CGAL's isotropic remeshing.
vtkPolyData* OuterSurface()
{
  static vtkSmartPointer<vtkPolyData> outer;
  if (!outer)
  {
    vtkPolyData* smooth = Smoothed();
    vtkDataArray* labels = smooth->GetCellData()->GetArray("Labels");
    vtkNew<vtkCellArray> polys;
    vtkIdType npts;
    const vtkIdType* ids;
    vtkIdType t = 0;
    for (smooth->GetPolys()->InitTraversal(); smooth->GetPolys()->GetNextCell(npts, ids); ++t)
      if (labels->GetComponent(t, 1) == 0)
        polys->InsertNextCell(npts, ids);
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(smooth->GetPoints());
    pd->SetPolys(polys);
    vtkNew<vtkCleanPolyData> clean; // drop the points of the inner interfaces
    clean->SetInputData(pd);
    clean->PointMergingOff();
    clean->Update();
    outer = clean->GetOutput();
    outer->GetFieldData()->PassData(smooth->GetFieldData()); // VoxelSize, for the curvature fit
  }
  return outer;
}

/// The comparison with CGAL's uniform isotropic remeshing (3 iterations) on the phantom's
/// outer surface: MetricRemeshing at a tolerance (curvature metric, isotropic), then CGAL with
/// the edge length that gives the same triangle count; both measured against the outer surface.
void OuterRemesh(benchmark::State& state)
{
  const bool cgal = state.range(0) == 1;
  const double eps = state.range(1) / 100.0;
  static std::map<int, vtkIdType> ours; // triangles of our result, per tolerance
  vtkSMPTools::SetBackend("STDThread");
  vtkPolyData* outer = OuterSurface();
  vtkSmartPointer<vtkPolyData> result;
  double seconds = 0, secondsMetric = 0;
  for (auto _ : state)
  {
    if (!cgal)
    {
      result = MetricRemesh(outer, eps, 0.5, secondsMetric, seconds); // 0.5: the metric's default
      ours[static_cast<int>(state.range(1))] = result->GetNumberOfCells();
    }
    else
    {
      // Edge length for the same count (equilateral triangles of the surface's area), corrected
      // once by the count the first run gives; the second run is the one timed.
      const vtkIdType target =
        ours.count(static_cast<int>(state.range(1))) ? ours[static_cast<int>(state.range(1))] : 92000;
      double area = 0;
      vtkIdType npts;
      const vtkIdType* ids;
      for (outer->GetPolys()->InitTraversal(); outer->GetPolys()->GetNextCell(npts, ids);)
      {
        double p[3][3], u[3], v[3], n[3];
        for (int k = 0; k < 3; ++k)
          outer->GetPoint(ids[k], p[k]);
        vtkMath::Subtract(p[1], p[0], u);
        vtkMath::Subtract(p[2], p[0], v);
        vtkMath::Cross(u, v, n);
        area += 0.5 * vtkMath::Norm(n);
      }
      double length = std::sqrt(4.0 * area / (std::sqrt(3.0) * target));
      result = amBench::CgalIsotropicRemeshing(outer, length, 3);
      length *= std::sqrt(static_cast<double>(result->GetNumberOfCells()) / target);
      const auto t0 = std::chrono::steady_clock::now();
      result = amBench::CgalIsotropicRemeshing(outer, length, 3);
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      state.counters["edge_length_mm"] = length;
    }
  }
  SurfaceCounters(state, result, outer);
  state.counters["remesh_s"] = seconds;
  if (!cgal)
    state.counters["metric_s"] = secondsMetric;
}
// (method, tolerance in 1/100 mm): method 0 = amCurvatureMetric + amMetricRemeshing, 1 = CGAL
// isotropic_remeshing to the same triangle count.
BENCHMARK(OuterRemesh)
  ->ArgsProduct({ { 0, 1 }, { 10, 25, 50 } })
  ->Unit(benchmark::kSecond)
  ->Iterations(1)
  ->UseRealTime();
}

BENCHMARK_MAIN();
