// Foundation benchmarks: phantom generation at three resolutions, reading a real CT, writing
// and reading a label map. Each reports voxels per second and the process's peak memory.
#include "amImageReader.h"
#include "amImageWriter.h"
#include "amThoraxPhantomSource.h"

#include "vtkImageData.h"
#include "vtkNew.h"

#include <benchmark/benchmark.h>

#include <string>
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
  state.counters["voxels/s"] = benchmark::Counter(static_cast<double>(voxels), benchmark::Counter::kIsIterationInvariantRate);
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
}

BENCHMARK_MAIN();
