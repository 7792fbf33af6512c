// The surface -> TetGen chain on synthetic many-label maps (amSyntheticAtlasSource): seconds and peak
// memory per stage, and what the chain promises: every label a region, the Hausdorff distance
// against the tolerance, the worst element. Run: build/bin/BenchmarkAtlas [--benchmark_filter=...]
// Arguments: number of labels, voxels per side, variant (0 clean, 1 sheets of 1 mm, 2 noise 5 %,
// 3 voxels 2.5 mm along z).
#include "../Cxx/amAtlasChain.h"
#include "amMeshQuality.h"

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
    const int dims[3] = { side, side, variant == 3 ? side * 5 / 12 : side }; // 96: 40 slices of 2.5 mm
    const double spacing[3] = { 1, 1, variant == 3 ? 2.5 : 1.0 };
    amTest::AtlasChain chain(labels, 1, dims, spacing, variant == 1 ? 1.0 : 0.0, variant == 2 ? 0.05 : 0.0, eps);
    amSyntheticAtlasSource* src = chain.Source;
    amLabelSurface* surface = chain.Surface;
    amSurfaceSmoothing* smooth = chain.Smooth;
    amCurvatureMetric* metric = chain.Metric;
    amMetricRemeshing* remesh = chain.Remesh;
    amTetrahedralize* tetra = chain.Tetra;
    vtkNew<amMeshQuality> quality;
    quality->SetInputConnection(tetra->GetOutputPort());
    // The process's peak after each stage: a stage's own peak is where the figure first grows.
    const auto t0 = Clock::now();
    src->Update();
    const auto t1 = Clock::now();
    state.counters["peak_source_MB"] = PeakMegabytes();
    surface->Update();
    const auto t2 = Clock::now();
    state.counters["peak_surface_MB"] = PeakMegabytes();
    smooth->Update();
    const auto t3 = Clock::now();
    state.counters["peak_smooth_MB"] = PeakMegabytes();
    metric->Update();
    const auto t4 = Clock::now();
    state.counters["peak_metric_MB"] = PeakMegabytes();
    remesh->Update();
    const auto t5 = Clock::now();
    state.counters["peak_remesh_MB"] = PeakMegabytes();
    tetra->Update();
    const auto t6 = Clock::now();
    state.counters["peak_tetgen_MB"] = PeakMegabytes();
    const std::set<int> in = amTest::DistinctValues(src->GetOutput()->GetPointData()->GetScalars());
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
      std::set<int> regions = amTest::DistinctValues(tetra->GetOutput()->GetCellData()->GetArray("Region"));
      state.counters["regions"] = static_cast<double>(regions.size());
      quality->Update();
      vtkTable* table = vtkTable::SafeDownCast(quality->GetOutputDataObject(1));
      const vtkIdType last = table->GetNumberOfRows() - 1;
      state.counters["mean_Q"] = table->GetValueByName(last, "MeanQuality").ToDouble();
      state.counters["worst_Q"] = table->GetValueByName(last, "MaximumQuality").ToDouble();
      state.counters["min_dihedral"] = table->GetValueByName(last, "MinimumDihedralAngle").ToDouble();
      state.counters["slivers"] = static_cast<double>(tetra->GetNumberOfSlivers());
      state.counters["surface_moved_mm"] = tetra->GetSurfaceDeviation();
      state.counters["volume_misses"] = static_cast<double>(tetra->GetNumberOfVolumeMisses());
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
