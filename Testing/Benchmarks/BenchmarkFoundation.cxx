// Foundation benchmarks: phantom generation at three resolutions, reading a real CT, writing
// and reading a label map, a time series written by VTK's writer and on worker threads. Each
// reports its rate and the process's peak memory. And what a page touched afresh costs.
#include "amConcurrentXMLWriter.h"
#include "amImageReader.h"
#include "amImageWriter.h"
#include "amThoraxPhantomSource.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <cmath>
#include <cstring>

#include <benchmark/benchmark.h>

#include <string>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <vector>

namespace
{
double PeakMegabytes()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

void Phantom(benchmark::State& state)
{
  const double spacing = state.range(0) / 10.0;
  vtkIdType voxels = 0;
  for (auto _ : state)
  {
    vtkNew<amThoraxPhantomSource> src;
    src->SetSpacing(spacing, spacing, spacing);
    src->Update();
    voxels = vtkImageData::SafeDownCast(src->GetOutputDataObject(0))->GetNumberOfPoints();
  }
  state.counters["voxels"] = static_cast<double>(voxels);
  state.counters["voxels/s"] =
    benchmark::Counter(static_cast<double>(voxels), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_MB"] = PeakMegabytes();
}
BENCHMARK(Phantom)->Arg(20)->Arg(10)->Arg(5)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void ReadCardiacCT(benchmark::State& state)
{
  const std::string path = std::string(ANATOMESH_SHARED_DATA) + "/totalseg_cardiac_ct/aorta_report/ct_cropped.nii.gz";
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
  {
    state.SkipWithError("shared data absent");
    return;
  }
  for (auto _ : state)
  {
    vtkNew<amImageReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
  }
  state.counters["peak_MB"] = PeakMegabytes();
}
BENCHMARK(ReadCardiacCT)->Unit(benchmark::kMillisecond)->UseRealTime();

void WriteReadLabels(benchmark::State& state)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(1, 1, 1);
  src->Update();
  const std::string path = std::string(ANATOMESH_BENCH_TMP) + "/bench_labels.nii.gz";
  for (auto _ : state)
  {
    vtkNew<amImageWriter> writer;
    writer->SetInputConnection(src->GetOutputPort(1));
    writer->SetFileName(path.c_str());
    writer->Write();
    vtkNew<amImageReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
  }
  state.counters["peak_MB"] = PeakMegabytes();
}
BENCHMARK(WriteReadLabels)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

/// Frame k of a heart-sized time series: 22 x 22 x 21 points (10 k), 48 k tetrahedra (six per
/// cube), two point arrays that change from frame to frame.
vtkSmartPointer<vtkUnstructuredGrid> SeriesFrame(int k)
{
  const int n[3] = { 22, 22, 21 };
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x)
        points->InsertNextPoint(x * 1.3, y * 1.3, z * 1.3);
  grid->SetPoints(points);
  auto id = [&](int x, int y, int z) { return static_cast<vtkIdType>((z * n[1] + y) * n[0] + x); };
  static const int tets[6][4] = { { 0, 1, 3, 7 }, { 0, 3, 2, 7 }, { 0, 2, 6, 7 }, { 0, 6, 4, 7 }, { 0, 4, 5, 7 },
    { 0, 5, 1, 7 } };
  for (int z = 0; z + 1 < n[2]; ++z)
    for (int y = 0; y + 1 < n[1]; ++y)
      for (int x = 0; x + 1 < n[0]; ++x)
      {
        vtkIdType corner[8];
        for (int c = 0; c < 8; ++c)
          corner[c] = id(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1));
        for (const auto& t : tets)
        {
          const vtkIdType ids[4] = { corner[t[0]], corner[t[1]], corner[t[2]], corner[t[3]] };
          grid->InsertNextCell(VTK_TETRA, 4, ids);
        }
      }
  for (const char* name : { "u", "v" })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(grid->GetNumberOfPoints());
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
      a->SetValue(i, std::tanh(0.01 * i - 0.5 * k));
    grid->GetPointData()->AddArray(a);
  }
  return grid;
}

/// 101 frames written as the pipeline writes its time series: arg 0 by one
/// vtkXMLUnstructuredGridWriter per frame (VTK's own, the peer), arg N on N worker threads of
/// amConcurrentXMLWriter. Both inline binary, zlib level 1: the same bytes.
void WriteSeries(benchmark::State& state)
{
  const int threads = static_cast<int>(state.range(0)), frames = 101;
  std::vector<vtkSmartPointer<vtkUnstructuredGrid>> series;
  for (int k = 0; k < frames; ++k)
    series.push_back(SeriesFrame(k));
  auto path = [](int k) { return std::string(ANATOMESH_BENCH_TMP) + "/bench_frame_" + std::to_string(k) + ".vtu"; };
  for (auto _ : state)
  {
    if (threads == 0)
      for (int k = 0; k < frames; ++k)
      {
        vtkNew<vtkXMLUnstructuredGridWriter> writer;
        writer->SetInputData(series[k]);
        writer->SetFileName(path(k).c_str());
        writer->SetDataModeToBinary();
        writer->SetCompressorTypeToZLib();
        writer->SetCompressionLevel(1);
        writer->Write();
      }
    else
    {
      vtkNew<amConcurrentXMLWriter> files;
      files->SetNumberOfThreads(threads);
      for (int k = 0; k < frames; ++k)
        files->Write(series[k], path(k).c_str());
      if (!files->Finish())
        state.SkipWithError(files->GetErrorMessage());
    }
  }
  state.counters["frames_per_s"] = benchmark::Counter(frames, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["tetrahedra"] = static_cast<double>(series[0]->GetNumberOfCells());
  state.counters["peak_MB"] = PeakMegabytes();
}
BENCHMARK(WriteSeries)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();

// What a page costs the first time a process touches it against the next time: the reason the
// anatomesh command keeps freed memory between filters (docs/benchmarks.md, the allocator).
// Arg 0: 1 GB mapped afresh and written (every page a fault, zeroed by the kernel), then unmapped;
// arg 1: the same 1 GB mapped once before the timing, then written again.
void FirstTouch(benchmark::State& state)
{
  const size_t bytes = size_t(1) << 30;
  const bool again = state.range(0) == 1;
  auto map = [&]() {
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
      state.SkipWithError("cannot map 1 GB");
    return p == MAP_FAILED ? nullptr : static_cast<char*>(p);
  };
  char* kept = again ? map() : nullptr;
  if (again && !kept)
    return;
  if (kept)
    std::memset(kept, 1, bytes);
  for (auto _ : state)
  {
    char* p = again ? kept : map();
    if (!p)
      return;
    std::memset(p, 2, bytes);
    benchmark::DoNotOptimize(p[bytes - 1]);
    if (!again)
      munmap(p, bytes);
  }
  if (kept)
    munmap(kept, bytes);
  state.counters["GB_per_s"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(FirstTouch)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
}

BENCHMARK_MAIN();
