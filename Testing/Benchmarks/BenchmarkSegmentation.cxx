// Segmentation benchmarks: the phantom's heart (both blood pools) at 1 mm and 0.5 mm, in 3-D and
// slice-by-slice modes; classification and cleaning of the whole phantom at 1 mm; the whole domain
// at 1 mm (four clicks, the torso from the scan's own classes or fixed ranges, the landmarks); the real CT's
// dissected aorta (../shared/data) with the level set and the polar snakes, Dice against its mask.
// Prints seconds, the Dice reached and the process's peak memory. Run: build/bin/BenchmarkSegmentation
#include "amCardiacLandmarks.h"
#include "amImageReader.h"
#include "amIntensityClassifier.h"
#include "amLabelOverlap.h"
#include "amMorphologyCleaning.h"
#include "amSnakeSegmentation.h"
#include "amThoraxPhantomSource.h"
#include "amTorsoSegmentation.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
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

// The main job's segmentation at 1 mm: the snake from four clicks, the torso segmentation (arg 1:
// the scan's own classes; 0: fixed ranges), the landmarks; each stage's seconds and the least Dice.
void WholeDomain(benchmark::State& state)
{
  amThoraxPhantomSource* src = Phantom(10);
  using Clock = std::chrono::steady_clock;
  double snakeSeconds = 0, torsoSeconds = 0, landmarkSeconds = 0, worst = 1;
  for (auto _ : state)
  {
    const auto t0 = Clock::now();
    vtkNew<amSnakeSegmentation> snake;
    snake->SetInputConnection(src->GetOutputPort(0));
    const double seeds[4][4] = { { 29.4, -24.1, -28.0, 6 }, { -15.0, -25.0, -28.0, 7 }, { 5.0, 40.0, 0.0, 8 },
      { 5.0, -20.0, 30.0, 8 } };
    for (const auto& x : seeds)
      snake->AddSeed(x[0], x[1], x[2], x[3]);
    snake->Update();
    const auto t1 = Clock::now();
    vtkNew<amTorsoSegmentation> torso;
    torso->SetInputConnection(src->GetOutputPort(0));
    torso->SetOrganConnection(snake->GetOutputPort());
    torso->SetAutomaticClasses(state.range(0) != 0);
    torso->Update();
    const auto t2 = Clock::now();
    vtkNew<amCardiacLandmarks> landmarks;
    landmarks->SetInputConnection(torso->GetOutputPort());
    landmarks->Update();
    const auto t3 = Clock::now();
    snakeSeconds = std::chrono::duration<double>(t1 - t0).count();
    torsoSeconds = std::chrono::duration<double>(t2 - t1).count();
    landmarkSeconds = std::chrono::duration<double>(t3 - t2).count();
    auto* truth = vtkImageData::SafeDownCast(src->GetOutputDataObject(1));
    for (int l = 1; l <= 10; ++l)
      worst = std::min(worst, Dice(torso->GetOutput(), truth, l));
  }
  state.counters["snake_s"] = snakeSeconds;
  state.counters["torso_s"] = torsoSeconds;
  state.counters["landmarks_s"] = landmarkSeconds;
  state.counters["worst_dice"] = worst;
  state.counters["peak_MB"] = PeakMegabytes();
}
BENCHMARK(WholeDomain)->Arg(1)->Arg(0)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// The aorta of the real cardiac CT, with cardiac_aorta.xml's nine seeds: the level-set snake (the
// old pipeline's settings) against the polar snakes. Arg: contour model (0 level set, 1 polar).
void RealAorta(benchmark::State& state)
{
  const std::string dir = std::string(ANATOMESH_SHARED_DATA) + "/totalseg_cardiac_ct/aorta_report/";
  struct stat st;
  if (::stat((dir + "aorta.nii.gz").c_str(), &st) != 0)
  {
    state.SkipWithError("../shared/data/totalseg_cardiac_ct is absent");
    return;
  }
  vtkNew<amImageReader> ct, mask;
  ct->SetFileName((dir + "ct_cropped.nii.gz").c_str());
  mask->SetFileName((dir + "aorta.nii.gz").c_str());
  ct->Update();
  vtkNew<amSnakeSegmentation> seg;
  seg->SetInputConnection(ct->GetOutputPort());
  seg->SetMode(amSnakeSegmentation::SliceBySlice);
  seg->SetMaximumAreaChange(1.5);
  if (state.range(0))
    seg->SetContourModel(amSnakeSegmentation::Polar);
  else
  {
    seg->SetAdaptiveSliceStatistics(true);
    seg->SetIntensityTolerance(1.5);
    seg->SetMinimumIntensityWindow(60);
  }
  const double seeds[][3] = { { 1.8, -140.2, 552.2 }, { -2.7, -135.7, 592.7 }, { 28.8, -116.2, 633.2 },
    { 7.8, -188.2, 675.2 }, { 33.3, -99.7, 675.2 }, { 4.8, -180.7, 715.7 }, { 22.8, -113.2, 715.7 },
    { 19.8, -143.2, 757.7 }, { 18.3, -156.7, 747.2 } };
  for (const auto& x : seeds)
    seg->AddSeed(x[0], x[1], x[2], 1);
  for (auto _ : state)
  {
    seg->Modified();
    seg->Update();
  }
  vtkNew<amLabelOverlap> overlap;
  overlap->SetInputConnection(0, seg->GetOutputPort());
  overlap->SetInputConnection(1, mask->GetOutputPort());
  overlap->Update();
  state.counters["dice_aorta"] = overlap->GetDice(1);
  state.counters["peak_MB"] = PeakMegabytes();
}
BENCHMARK(RealAorta)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
}

BENCHMARK_MAIN();
