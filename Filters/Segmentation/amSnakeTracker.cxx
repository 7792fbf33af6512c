#include "amSnakeTracker.h"

#include "amIntensityPeaks.h"

#include "amSnakeLevelSet.h"

#include "vtkSMPTools.h"

#include <itkSmoothingRecursiveGaussianImageFilter.h>

#include <algorithm>

using namespace amSnakeLevelSet;

amSnakeTracker::amSnakeTracker(const Parameters& parameters, const double spacing[3])
  : P(parameters)
{
  std::copy(spacing, spacing + 3, this->Spacing);
  // The initial contour must span a few voxels, or curvature collapses it before it can grow.
  this->InitialRadius = std::max(this->P.SeedRadius, 2.5 * std::max(spacing[0], std::max(spacing[1], spacing[2])));
}

void amSnakeTracker::SetRegion(const int lo[3], const int size[3], const std::vector<float>& intensities)
{
  this->SetSmoothedRegion(lo, size, Smooth(size, this->Spacing, this->P.SmoothingSigma, intensities));
}

void amSnakeTracker::SetSmoothedRegion(const int lo[3], const int size[3], std::vector<float> smoothed)
{
  std::copy(lo, lo + 3, this->Lo);
  std::copy(size, size + 3, this->Size);
  this->Feature = std::move(smoothed);
}

std::vector<float> amSnakeTracker::Smooth(
  const int size[3], const double spacing[3], double sigma, std::vector<float> values)
{
  if (sigma <= 0)
    return values;
  auto box = NewImage<FloatImage<3>>(size, spacing);
  std::copy(values.begin(), values.end(), box->GetBufferPointer());
  auto smooth = itk::SmoothingRecursiveGaussianImageFilter<FloatImage<3>, FloatImage<3>>::New();
  smooth->SetInput(box);
  smooth->SetSigma(sigma);
  smooth->Update();
  const float* f = smooth->GetOutput()->GetBufferPointer();
  values.assign(f, f + values.size());
  return values;
}

void amSnakeTracker::MeasureSeeds(const std::vector<std::array<double, 3>>& seeds)
{
  this->Seeds = seeds;
  this->SeedStats.clear();
  const int* rd = this->Size;
  const float* fv = this->Feature.data();
  double sum = 0, sum2 = 0;
  long count = 0;
  for (size_t s = 0; s < seeds.size(); ++s)
  {
    const int r[3] = { static_cast<int>(std::ceil(this->P.SeedRadius / this->Spacing[0])),
      static_cast<int>(std::ceil(this->P.SeedRadius / this->Spacing[1])),
      static_cast<int>(std::ceil(this->P.SeedRadius / this->Spacing[2])) };
    const int c[3] = { static_cast<int>(std::lround(seeds[s][0])) - this->Lo[0],
      static_cast<int>(std::lround(seeds[s][1])) - this->Lo[1],
      static_cast<int>(std::lround(seeds[s][2])) - this->Lo[2] };
    double ssum = 0, ssum2 = 0;
    long scount = 0;
    for (int k = std::max(0, c[2] - r[2]); k <= std::min(rd[2] - 1, c[2] + r[2]); ++k)
      for (int j = std::max(0, c[1] - r[1]); j <= std::min(rd[1] - 1, c[1] + r[1]); ++j)
        for (int i = std::max(0, c[0] - r[0]); i <= std::min(rd[0] - 1, c[0] + r[0]); ++i)
          if (this->BallDistance(s, i, j, k) <= this->P.SeedRadius)
          {
            const double v = fv[this->At(i, j, k)];
            sum += v;
            sum2 += v * v;
            ssum += v;
            ssum2 += v * v;
            ++count;
            ++scount;
          }
    if (scount == 0)
    {
      const double v = fv[this->At(c[0], c[1], c[2])];
      sum += v;
      sum2 += v * v;
      ssum = v;
      ssum2 = v * v;
      scount = 1;
      ++count;
    }
    this->SeedStats.push_back(
      { ssum / scount, std::sqrt(std::max(0.0, ssum2 / scount - (ssum / scount) * (ssum / scount))) });
  }
  this->Mean = sum / count;
  this->Deviation = std::sqrt(std::max(0.0, sum2 / count - this->Mean * this->Mean));
}

bool amSnakeTracker::Segment(
  double imageMax, const std::function<void(double)>& progress, const std::function<bool()>& abort)
{
  this->Progress = progress;
  this->Abort = abort;
  this->Error.clear();
  this->Elapsed = 0;
  this->Boxed = 0;
  double tlo = this->P.LowerThreshold, thi = this->P.UpperThreshold;
  if (this->P.AutomaticThresholds)
  {
    const double half = std::max(this->P.IntensityTolerance * this->Deviation, this->P.MinimumIntensityWindow);
    tlo = this->Mean - half;
    thi = this->Mean + half;
    // The window stops half-way to the nearest other population of the region (the partial-volume
    // boundary), so a neighbour within the window (an enhanced wall beside a late-phase blood pool)
    // is not taken; the seeds' own spread is the organ's.
    const amIntensityPeaks peaks = amIntensityPeaks::Find(this->Feature);
    const double own = this->P.IntensityTolerance * this->Deviation;
    double peak;
    if (peaks.Below(this->Mean, own, peak))
      tlo = std::max(tlo, 0.5 * (this->Mean + peak));
    if (peaks.Above(this->Mean, own, peak))
      thi = std::min(thi, 0.5 * (this->Mean + peak));
  }
  this->InsideMask.assign(static_cast<size_t>(this->Size[0]) * this->Size[1] * this->Size[2], 0);
  if (!this->Run(tlo, thi, nullptr, 0.15, 0.55))
    return false;
  // Refinement: the contour should stop half-way between the organ's intensity and that of its
  // surroundings (where partial volume puts the true boundary), not at the edge of the
  // statistical interval. Sample a 2-voxel shell outside (beyond the smoothing's blur), move the
  // facing threshold there (never narrowing the interval) and evolve again.
  if (this->P.ContourModel == Parameters::Polar)
  {
    tlo = this->P.OutsideThreshold;
    thi = imageMax;
  }
  else if (this->P.AutomaticThresholds && this->P.RefineToHalfContrast)
  {
    const std::vector<unsigned char> first = this->InsideMask;
    auto mask3 = NewImage<MaskImage<3>>(this->Size, this->Spacing);
    std::copy(first.begin(), first.end(), mask3->GetBufferPointer());
    // Beyond the blur of the smoothing, two voxels thick.
    const double voxel = std::max(this->Spacing[0], std::max(this->Spacing[1], this->Spacing[2]));
    const double shellIn = std::max(2.0 * voxel, 2.0 * this->P.SmoothingSigma), shellOut = shellIn + 2.0 * voxel;
    const double finest = std::min(this->Spacing[0], std::min(this->Spacing[1], this->Spacing[2]));
    auto dist = SignedDistanceNear<3>(
      mask3, static_cast<int>(std::ceil(shellOut / finest)) + 1, static_cast<float>(2 * shellOut));
    const float* dv = dist->GetBufferPointer();
    const float* fv = this->Feature.data();
    double osum = 0;
    long ocount = 0;
    for (size_t i = 0; i < first.size(); ++i)
      if (dv[i] > shellIn && dv[i] <= shellOut)
      {
        osum += fv[i];
        ++ocount;
      }
    if (ocount > 0 && std::count(first.begin(), first.end(), 1) > 0)
    {
      const double outside = osum / ocount, mid = 0.5 * (this->Mean + outside);
      bool changed = false;
      if (outside < this->Mean && mid < tlo)
      {
        tlo = mid;
        changed = true;
      }
      else if (outside > this->Mean && mid > thi)
      {
        thi = mid;
        changed = true;
      }
      if (changed && !this->Run(tlo, thi, this->P.Mode == Parameters::ThreeD ? &first : nullptr, 0.7, 0.3))
        return false;
    }
  }
  this->Low = tlo;
  this->High = thi;
  return true;
}

bool amSnakeTracker::Run(double lo, double hi, const std::vector<unsigned char>* initial, double pa, double pb)
{
  std::fill(this->InsideMask.begin(), this->InsideMask.end(), 0);
  if (this->P.Mode == Parameters::ThreeD)
    return this->RunThreeD(lo, hi, initial, pa, pb);
  if (this->P.ContourModel == Parameters::Polar)
    return this->RunPolar();
  return this->RunSlices(lo, hi);
}

bool amSnakeTracker::RunCoarse(double lo, double hi, std::vector<unsigned char>& inside)
{
  const int* rd = this->Size;
  const int cs[3] = { (rd[0] + 1) / 2, (rd[1] + 1) / 2, (rd[2] + 1) / 2 };
  const double csp[3] = { 2 * this->Spacing[0], 2 * this->Spacing[1], 2 * this->Spacing[2] };
  auto feature = NewImage<FloatImage<3>>(cs, csp);
  auto phi = NewImage<FloatImage<3>>(cs, csp);
  float* fv = feature->GetBufferPointer();
  float* pv = phi->GetBufferPointer();
  // The seed balls at least 2.5 coarse voxels in radius, as at full resolution.
  const double radius = std::max(this->InitialRadius, 2.5 * std::max(csp[0], std::max(csp[1], csp[2])));
  auto coarse = [&cs](int i, int j, int k) { return (static_cast<size_t>(k) * cs[1] + j) * cs[0] + i; };
  vtkSMPTools::For(0, cs[2], [&](vtkIdType k0, vtkIdType k1) {
    for (int k = static_cast<int>(k0); k < k1; ++k)
      for (int j = 0; j < cs[1]; ++j)
        for (int i = 0; i < cs[0]; ++i)
        {
          double sum = 0;
          int n = 0;
          for (int c = 2 * k; c < std::min(2 * k + 2, rd[2]); ++c)
            for (int b = 2 * j; b < std::min(2 * j + 2, rd[1]); ++b)
              for (int a = 2 * i; a < std::min(2 * i + 2, rd[0]); ++a)
              {
                sum += this->Feature[this->At(a, b, c)];
                ++n;
              }
          fv[coarse(i, j, k)] = static_cast<float>(sum / n);
          pv[coarse(i, j, k)] = static_cast<float>(this->NearestSeed(2 * i + 0.5, 2 * j + 0.5, 2 * k + 0.5) - radius);
        }
  });
  const Parameters& p = this->P;
  const amSnakeLevelSet::Parameters lsp = LevelSetParameters(p);
  MaskImage<3>::Pointer mask;
  try
  {
    mask = Evolve<3>(feature, phi, lo, hi, lsp, p.NumberOfIterations, nullptr, &this->Elapsed);
  }
  catch (const itk::ExceptionObject& e)
  {
    this->Error = e.GetDescription();
    return false;
  }
  const unsigned char* m = mask->GetBufferPointer();
  inside.assign(static_cast<size_t>(rd[0]) * rd[1] * rd[2], 0);
  for (int k = 0; k < rd[2]; ++k)
    for (int j = 0; j < rd[1]; ++j)
      for (int i = 0; i < rd[0]; ++i)
        inside[this->At(i, j, k)] = m[coarse(i / 2, j / 2, k / 2)];
  return true;
}

bool amSnakeTracker::RunThreeD(double lo, double hi, const std::vector<unsigned char>* initial, double pa, double pb)
{
  const int* rd = this->Size;
  // The first evolution at twice the voxel size: the front crosses the organ in half the
  // iterations over an eighth of the voxels, and the full resolution then moves it by a voxel or
  // two. It keeps its full iteration limit there, so that a part too thin for the coarse grid
  // still grows from the rest. An organ the coarse grid loses entirely starts from its seeds.
  std::vector<unsigned char> coarse;
  bool fromCoarse = false;
  if (!initial && this->P.CoarseToFine && std::min(rd[0], std::min(rd[1], rd[2])) >= 16)
  {
    if (!this->RunCoarse(lo, hi, coarse))
      return false;
    fromCoarse = std::find(coarse.begin(), coarse.end(), 1) != coarse.end();
    if (fromCoarse)
      initial = &coarse;
    if (this->Progress)
      this->Progress(pa + 0.3 * pb);
    pa += 0.3 * pb;
    pb *= 0.7;
  }
  const Parameters& p = this->P;
  const int iterations = initial && !fromCoarse ? std::min(200, p.NumberOfIterations) : p.NumberOfIterations;
  std::function<void(double)> progress;
  if (this->Progress)
    progress = [this, pa, pb](double f) { this->Progress(pa + pb * f); };
  if (initial)
  {
    const int box = this->EvolveInBox(lo, hi, *initial, iterations, progress);
    if (box != BoxTooSmall)
      return box == BoxDone;
  }
  FloatImage<3>::Pointer phi;
  if (initial)
  {
    auto mask = NewImage<MaskImage<3>>(rd, this->Spacing);
    std::copy(initial->begin(), initial->end(), mask->GetBufferPointer());
    phi = PhiFromMask(mask);
  }
  else
  {
    phi = NewImage<FloatImage<3>>(rd, this->Spacing);
    float* pv = phi->GetBufferPointer();
    vtkSMPTools::For(0, rd[2], [&](vtkIdType k0, vtkIdType k1) {
      for (vtkIdType k = k0; k < k1; ++k)
        for (int j = 0; j < rd[1]; ++j)
          for (int i = 0; i < rd[0]; ++i)
            pv[this->At(i, j, static_cast<int>(k))] =
              static_cast<float>(this->NearestSeed(i, j, static_cast<double>(k)) - this->InitialRadius);
    });
  }
  auto feature = NewImage<FloatImage<3>>(rd, this->Spacing);
  std::copy(this->Feature.begin(), this->Feature.end(), feature->GetBufferPointer());
  const amSnakeLevelSet::Parameters lsp = LevelSetParameters(p);
  try
  {
    auto mask = Evolve<3>(feature, phi, lo, hi, lsp, iterations, progress, &this->Elapsed);
    std::copy(mask->GetBufferPointer(), mask->GetBufferPointer() + this->InsideMask.size(), this->InsideMask.begin());
  }
  catch (const itk::ExceptionObject& e)
  {
    this->Error = e.GetDescription();
    return false;
  }
  return true;
}
