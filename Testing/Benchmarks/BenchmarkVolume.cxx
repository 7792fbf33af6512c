// Volume benchmarks: the remeshed multi-material phantom surface -> tetrahedra (amTetrahedralize,
// TetGen), the phantom label map -> tetrahedra (amLabelMapTetrahedralize, CGAL Mesh_3), and the
// quality table (amMeshQuality). The surface is prepared once per size (label
// surface, smoothing, curvature metric, remeshing: not timed here, see BenchmarkSurface).
// Prints seconds, tetrahedra per second, the quality figures and the peak memory of this process
// and of the TetGen child process (TetGen runs in a forked child).
// Run: build/bin/BenchmarkVolume [--benchmark_filter=...]
#include "amCurvatureMetric.h"
#include "amLabelMapTetrahedralize.h"
#include "amLabelSurface.h"
#include "amMeshQuality.h"
#include "amMetricRemeshing.h"
#include "amSurfaceSmoothing.h"
#include "amTetrahedralize.h"
#include "amThoraxPhantomSource.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <benchmark/benchmark.h>

#include <map>
#include <sys/resource.h>

namespace
{
double PeakMegabytes(int who)
{
  struct rusage u;
  getrusage(who, &u);
  return u.ru_maxrss / 1024.0;
}

/// The remeshed phantom surface: spacing (tenths of mm) and tolerance (hundredths of mm).
vtkPolyData* Surface(int spacing, int tolerance)
{
  static std::map<std::pair<int, int>, vtkSmartPointer<vtkPolyData>> cache;
  auto& s = cache[{ spacing, tolerance }];
  if (!s)
  {
    const double h = spacing / 10.0, eps = tolerance / 100.0;
    vtkNew<amThoraxPhantomSource> src;
    src->SetSpacing(h, h, h);
    vtkNew<amLabelSurface> ls;
    ls->SetInputConnection(src->GetOutputPort(1));
    ls->SetComputeTopology(false);
    vtkNew<amSurfaceSmoothing> sm;
    sm->SetInputConnection(ls->GetOutputPort());
    vtkNew<amCurvatureMetric> cm;
    cm->SetInputConnection(sm->GetOutputPort());
    cm->SetTolerance(eps);
    cm->SetMinimumSize(h);
    cm->SetAnisotropic(false);
    vtkNew<amMetricRemeshing> rm;
    rm->SetInputConnection(cm->GetOutputPort());
    rm->SetTolerance(eps);
    rm->Update();
    s = vtkSmartPointer<vtkPolyData>::New();
    s->ShallowCopy(rm->GetOutput());
  }
  return s;
}

void Tetrahedralize(benchmark::State& state)
{
  vtkPolyData* surface = Surface(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  vtkIdType tets = 0;
  vtkSmartPointer<vtkTable> table;
  for (auto _ : state)
  {
    vtkNew<amTetrahedralize> t;
    t->SetInputData(surface);
    t->SetImproveQuality(state.range(2) != 0);
    t->Update();
    tets = t->GetNumberOfTetrahedra();
    state.PauseTiming();
    vtkNew<amMeshQuality> q;
    q->SetInputConnection(t->GetOutputPort());
    q->Update();
    table = vtkTable::SafeDownCast(q->GetOutputDataObject(1));
    state.ResumeTiming();
  }
  state.counters["triangles"] = static_cast<double>(surface->GetNumberOfCells());
  state.counters["tetrahedra"] = static_cast<double>(tets);
  state.counters["tets_per_s"] =
    benchmark::Counter(static_cast<double>(tets), benchmark::Counter::kIsIterationInvariantRate);
  const vtkIdType all = table->GetNumberOfRows() - 1;
  state.counters["meanQ"] = table->GetValueByName(all, "MeanQuality").ToDouble();
  state.counters["worstQ"] = table->GetValueByName(all, "MaximumQuality").ToDouble();
  state.counters["min_dihedral"] = table->GetValueByName(all, "MinimumDihedralAngle").ToDouble();
  state.counters["peak_MB"] = PeakMegabytes(RUSAGE_SELF);
  state.counters["tetgen_peak_MB"] = PeakMegabytes(RUSAGE_CHILDREN);
}

/// Statistics of the whole mesh (last row of amMeshQuality's table) as counters.
void QualityCounters(benchmark::State& state, vtkAlgorithmOutput* mesh)
{
  vtkNew<amMeshQuality> q;
  q->SetInputConnection(mesh);
  q->Update();
  vtkTable* table = vtkTable::SafeDownCast(q->GetOutputDataObject(1));
  const vtkIdType all = table->GetNumberOfRows() - 1;
  state.counters["meanQ"] = table->GetValueByName(all, "MeanQuality").ToDouble();
  state.counters["worstQ"] = table->GetValueByName(all, "MaximumQuality").ToDouble();
  state.counters["min_dihedral"] = table->GetValueByName(all, "MinimumDihedralAngle").ToDouble();
  state.counters["surface_triangles"] = table->GetValueByName(all, "nt").ToDouble();
}

/// CGAL Mesh_3 from the phantom label map: spacing (tenths of mm), improvement (0/1); sizes
/// scale with the spacing.
void LabelMapCGAL(benchmark::State& state)
{
  const double h = state.range(0) / 10.0;
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(h, h, h);
  src->Update();
  vtkNew<amLabelMapTetrahedralize> m;
  m->SetInputConnection(src->GetOutputPort(1));
  m->SetFacetSize(2 * h);
  m->SetFacetDistance(0.25 * h);
  m->SetCellSize(3 * h);
  m->SetImproveQuality(state.range(1) != 0);
  for (auto _ : state)
  {
    m->Modified();
    m->Update();
  }
  const double tets = static_cast<double>(m->GetNumberOfTetrahedra());
  state.counters["tetrahedra"] = tets;
  state.counters["tets_per_s"] = benchmark::Counter(tets, benchmark::Counter::kIsIterationInvariantRate);
  QualityCounters(state, m->GetOutputPort());
  state.counters["peak_MB"] = PeakMegabytes(RUSAGE_SELF);
}

void Quality(benchmark::State& state)
{
  vtkNew<amTetrahedralize> t;
  t->SetInputData(Surface(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
  t->Update();
  for (auto _ : state)
  {
    vtkNew<amMeshQuality> q;
    q->SetInputConnection(t->GetOutputPort());
    q->Update();
  }
  state.counters["tetrahedra"] = static_cast<double>(t->GetNumberOfTetrahedra());
}
}

// Phantom at 2 mm (tolerance 0.5 mm) and at 1 mm (tolerance 0.2 mm), TetGen alone and with the
// quality improvement (third argument).
BENCHMARK(Tetrahedralize)
  ->Args({ 20, 50, 0 })
  ->Args({ 20, 50, 1 })
  ->Args({ 10, 20, 0 })
  ->Args({ 10, 20, 1 })
  ->Unit(benchmark::kSecond)
  ->Iterations(1);
BENCHMARK(LabelMapCGAL)
  ->Args({ 40, 0 })
  ->Args({ 40, 1 })
  ->Args({ 20, 0 })
  ->Args({ 20, 1 })
  ->Unit(benchmark::kSecond)
  ->Iterations(1);
BENCHMARK(Quality)->Args({ 20, 50 })->Args({ 10, 20 })->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_MAIN();
