// Segmentation benchmarks: the phantom's heart (both blood pools) at 1 mm and 0.5 mm, in 3-D and
// slice-by-slice modes; classification and cleaning of the whole phantom at 1 mm. Prints seconds,
// the Dice of each pool and the process's peak memory. Run: build/bin/BenchmarkSegmentation
#include "amIntensityClassifier.h"
#include "amMorphologyCleaning.h"
#include "amSnakeSegmentation.h"
#include "amThoraxPhantomSource.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <benchmark/benchmark.h>

#include <map>
#include <sys/resource.h>

namespace
{
double PeakMegabytes()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

// One phantom per resolution, kept for all runs (its generation is benchmarked elsewhere).
amThoraxPhantomSource* Phantom(int tenthsOfMm)
{
  static std::map<int, vtkSmartPointer<amThoraxPhantomSource>> cache;
  auto& src = cache[tenthsOfMm];
  if (!src)
  {
    src = vtkSmartPointer<amThoraxPhantomSource>::New();
    const double s = tenthsOfMm / 10.0;
    src->SetSpacing(s, s, s);
    if (tenthsOfMm < 10)
      src->SetFieldOfView(200, 160, 150); // the heart's neighbourhood at 0.5 mm (32 M voxels)
    src->Update();
  }
  return src;
}

double Dice(vtkImageData* seg, vtkImageData* truth, int label)
{
  vtkDataArray* a = seg->GetPointData()->GetScalars();
  vtkDataArray* b = truth->GetPointData()->GetScalars();
  long both = 0, na = 0, nb = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    const bool p = a->GetComponent(i, 0) == label, q = b->GetComponent(i, 0) == label;
    both += p && q;
    na += p;
    nb += q;
  }
  return 2.0 * both / (na + nb);
}

void HeartSnake(benchmark::State& state)
{
  amThoraxPhantomSource* src = Phantom(static_cast<int>(state.range(0)));
  vtkNew<amSnakeSegmentation> seg;
  for (auto _ : state)
  {
    seg->RemoveAllSeeds();
    seg->SetInputConnection(src->GetOutputPort(0));
    seg->SetMode(static_cast<int>(state.range(1)));
    for (int l : { 6, 7 })
    {
      double c[3];
      src->GetOrganCenter(l, c);
      seg->AddSeed(c[0], c[1], c[2], l);
    }
    seg->Modified();
    seg->Update();
  }
  auto* truth = vtkImageData::SafeDownCast(src->GetOutputDataObject(1));
  state.counters["dice_LV"] = Dice(seg->GetOutput(), truth, 6);
  state.counters["dice_RV"] = Dice(seg->GetOutput(), truth, 7);
  state.counters["peak_MB"] = PeakMegabytes();
}
// Args: spacing in tenths of a millimetre, mode (0 = 3-D, 1 = slice by slice).
BENCHMARK(HeartSnake)
  ->Args({ 10, 0 })
  ->Args({ 10, 1 })
  ->Args({ 5, 0 })
  ->Args({ 5, 1 })
  ->Unit(benchmark::kSecond)
  ->Iterations(1)
  ->UseRealTime();

void ClassifyAndClean(benchmark::State& state)
{
  amThoraxPhantomSource* src = Phantom(10);
  for (auto _ : state)
  {
    vtkNew<amIntensityClassifier> cls;
    cls->SetInputConnection(src->GetOutputPort(0));
    vtkNew<amMorphologyCleaning> clean;
    clean->SetInputConnection(cls->GetOutputPort(0));
    clean->SetOperation(amMorphologyCleaning::Open);
    clean->SetRadius(1.5);
    clean->SetMinimumComponentVolume(100);
    clean->SetSmoothingSigma(state.range(0) ? 1.0 : 0.0);
    clean->Update();
  }
  state.counters["peak_MB"] = PeakMegabytes();
}
BENCHMARK(ClassifyAndClean)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
}

BENCHMARK_MAIN();
