// The surface -> TetGen chain on synthetic many-label maps (amSyntheticAtlasSource): seconds and peak
// memory per stage, and what the chain promises: every label a region, the Hausdorff distance
// against the tolerance, the worst element. Run: build/bin/BenchmarkAtlas [--benchmark_filter=...]
// Arguments: number of labels, voxels per side, variant (0 clean, 1 sheets of 1 mm, 2 noise 5 %,
// 3 voxels 2.5 mm along z).
#include "amCurvatureMetric.h"
#include "amLabelSurface.h"
#include "amMeshQuality.h"
#include "amMetricRemeshing.h"
#include "amSurfaceSmoothing.h"
#include "amSyntheticAtlasSource.h"
#include "amTetrahedralize.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <set>
#include <sys/resource.h>

namespace
{
double PeakMegabytes()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

std::set<int> LabelsOf(vtkDataArray* a)
{
  std::set<int> s;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    s.insert(static_cast<int>(a->GetTuple1(i)));
  return s;
}

void Chain(benchmark::State& state)
{
  vtkSMPTools::SetBackend("STDThread");
  const int labels = static_cast<int>(state.range(0)), side = static_cast<int>(state.range(1));
  const int variant = static_cast<int>(state.range(2));
  const double eps = 0.5;
  for (auto _ : state)
  {
    using Clock = std::chrono::steady_clock;
    auto seconds = [](
                     Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
    vtkNew<amSyntheticAtlasSource> src;
    src->SetNumberOfLabels(labels);
    src->SetDimensions(side, side, variant == 3 ? side * 5 / 12 : side); // 96: 40 slices of 2.5 mm
    if (variant == 3)
      src->SetSpacing(1, 1, 2.5);
    src->SetSheetWidth(variant == 1 ? 1.0 : 0.0);
    src->SetNoiseFraction(variant == 2 ? 0.05 : 0.0);
    vtkNew<amLabelSurface> surface;
    surface->SetInputConnection(src->GetOutputPort());
    surface->SetComputeTopology(false);
    vtkNew<amSurfaceSmoothing> smooth;
    smooth->SetInputConnection(surface->GetOutputPort());
    vtkNew<amCurvatureMetric> metric;
    metric->SetInputConnection(smooth->GetOutputPort());
    metric->SetTolerance(eps);
    metric->SetMinimumSize(1.0);
    metric->SetAnisotropic(false);
    vtkNew<amMetricRemeshing> remesh;
    remesh->SetInputConnection(metric->GetOutputPort());
    remesh->SetTolerance(eps);
    vtkNew<amTetrahedralize> tetra;
    tetra->SetInputConnection(remesh->GetOutputPort());
    vtkNew<amMeshQuality> quality;
    quality->SetInputConnection(tetra->GetOutputPort());
    const auto t0 = Clock::now();
    src->Update();
    const auto t1 = Clock::now();
    surface->Update();
    const auto t2 = Clock::now();
    smooth->Update();
    const auto t3 = Clock::now();
    metric->Update();
    const auto t4 = Clock::now();
    remesh->Update();
    const auto t5 = Clock::now();
    tetra->Update();
    const auto t6 = Clock::now();
    const std::set<int> in = LabelsOf(src->GetOutput()->GetPointData()->GetScalars());
    state.counters["labels"] = static_cast<double>(in.size() - in.count(0));
    state.counters["surface_tris"] = surface->GetOutput()->GetNumberOfCells();
    state.counters["remeshed_tris"] = remesh->GetOutput()->GetNumberOfCells();
    state.counters["hausdorff_mm"] = remesh->GetHausdorff();
    state.counters["surface_s"] = seconds(t1, t2);
    state.counters["smooth_s"] = seconds(t2, t3);
    state.counters["metric_s"] = seconds(t3, t4);
    state.counters["remesh_s"] = seconds(t4, t5);
    state.counters["tetgen_s"] = seconds(t5, t6);
    const vtkIdType tets = tetra->GetOutput()->GetNumberOfCells();
    state.counters["tetrahedra"] = static_cast<double>(tets);
    if (tets > 0)
    {
      std::set<int> regions = LabelsOf(tetra->GetOutput()->GetCellData()->GetArray("Region"));
      state.counters["regions"] = static_cast<double>(regions.size());
      quality->Update();
      vtkTable* table = vtkTable::SafeDownCast(quality->GetOutputDataObject(1));
      const vtkIdType last = table->GetNumberOfRows() - 1;
      state.counters["mean_Q"] = table->GetValueByName(last, "MeanQuality").ToDouble();
      state.counters["worst_Q"] = table->GetValueByName(last, "MaximumQuality").ToDouble();
      state.counters["min_dihedral"] = table->GetValueByName(last, "MinimumDihedralAngle").ToDouble();
    }
    state.counters["peak_MB"] = PeakMegabytes();
  }
}
}

BENCHMARK(Chain)
  ->ArgsProduct({ { 30, 100 }, { 96 }, { 0, 1, 2, 3 } })
  ->Args({ 700, 160, 0 })
  ->Unit(benchmark::kSecond)
  ->Iterations(1)
  ->UseRealTime();

BENCHMARK_MAIN();
