#include "amSnakeTracker.h"

#include "amSnakeLevelSet.h"

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryErodeImageFilter.h>

#include <map>

using namespace amSnakeLevelSet;

namespace
{
/// A new 2-D image on the slices' grid.
template<typename TImage>
typename TImage::Pointer NewSliceImage(const typename TImage::RegionType& region, const FloatImage<2>::SpacingType& sp)
{
  auto img = TImage::New();
  img->SetRegions(region);
  img->SetSpacing(sp);
  img->Allocate();
  return img;
}

/// The section shrunk by a pixel (the start of the next slice's evolution), or the section itself
/// where nothing would be left.
MaskImage<2>::Pointer Eroded(MaskImage<2>* section)
{
  auto erode =
    itk::BinaryErodeImageFilter<MaskImage<2>, MaskImage<2>, itk::BinaryBallStructuringElement<unsigned char, 2>>::New();
  itk::BinaryBallStructuringElement<unsigned char, 2> ball;
  ball.SetRadius(1);
  ball.CreateStructuringElement();
  erode->SetKernel(ball);
  erode->SetInput(section);
  erode->SetForegroundValue(1);
  erode->Update();
  if (Count<2>(erode->GetOutput()) == 0)
    return section;
  return erode->GetOutput();
}

/// The intensity window around a mean: tolerance times the spread, at least the minimum window.
void Window(double mean, double spread, const amSnakeTracker::Parameters& p, double& lo, double& hi)
{
  const double half = std::max(p.IntensityTolerance * spread, p.MinimumIntensityWindow);
  lo = mean - half;
  hi = mean + half;
}

/// The mean and spread of the feature under the mask; false for an empty mask.
bool MaskedStatistics(const MaskImage<2>* mask, const FloatImage<2>* feature, size_t n, double& mean, double& spread)
{
  double a = 0, a2 = 0;
  long c = 0;
  for (size_t q = 0; q < n; ++q)
    if (mask->GetBufferPointer()[q])
    {
      const double f = feature->GetBufferPointer()[q];
      a += f;
      a2 += f * f;
      ++c;
    }
  if (c == 0)
    return false;
  mean = a / c;
  spread = std::sqrt(std::max(0.0, a2 / c - mean * mean));
  return true;
}
}

// The paper's propagation: each section evolved as a 2-D threshold level set, from the seeds' balls
// in the seeds' slices, then slice after slice from the previous section (eroded by a pixel),
// until the section vanishes or changes abruptly.
bool amSnakeTracker::RunSlices(double tlo, double thi)
{
  const int* rd = this->Size;
  const float* fv = this->Feature.data();
  const Parameters& p = this->P;
  const amSnakeLevelSet::Parameters lsp = amSnakeLevelSet::LevelSetParameters(p);
  const int ax = p.SliceAxis, u = ax == 0 ? 1 : 0, v = ax == 2 ? 1 : 2;
  const int nu = rd[u], nv = rd[v], ns = rd[ax];
  const double pixelArea = this->Spacing[u] * this->Spacing[v];
  FloatImage<2>::RegionType region2;
  FloatImage<2>::SizeType size2 = { { static_cast<itk::SizeValueType>(nu), static_cast<itk::SizeValueType>(nv) } };
  region2.SetSize(size2);
  FloatImage<2>::SpacingType sp2;
  sp2[0] = this->Spacing[u];
  sp2[1] = this->Spacing[v];
  auto sliceFeature = [&](int is) {
    auto img = NewSliceImage<FloatImage<2>>(region2, sp2);
    for (int iv = 0; iv < nv; ++iv)
      for (int iu = 0; iu < nu; ++iu)
        img->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu] = fv[this->AtSlice(iu, iv, is)];
    return img;
  };
  std::vector<char> done(static_cast<size_t>(ns), 0);
  std::map<int, std::vector<size_t>> bySlice; // seeds by their slice
  for (size_t s = 0; s < this->Seeds.size(); ++s)
    bySlice[std::min(ns - 1, std::max(0, static_cast<int>(std::lround(this->Seeds[s][ax])) - this->Lo[ax]))].push_back(
      s);
  const int iterations2 = std::min(this->P.NumberOfIterations, 400);
  size_t started = 0;
  for (const auto& entry : bySlice)
  {
    const int s0 = entry.first;
    ++started;
    if (done[s0])
      continue;
    // The seed slice: balls cut by the slice.
    auto phi = NewSliceImage<FloatImage<2>>(region2, sp2);
    auto ballMask = NewSliceImage<MaskImage<2>>(region2, sp2);
    for (int iv = 0; iv < nv; ++iv)
      for (int iu = 0; iu < nu; ++iu)
      {
        int ijk[3];
        ijk[u] = iu;
        ijk[v] = iv;
        ijk[ax] = s0;
        double d = 1e30;
        for (size_t s : entry.second)
        {
          double q[3] = { static_cast<double>(ijk[0]), static_cast<double>(ijk[1]), static_cast<double>(ijk[2]) };
          q[ax] = this->Seeds[s][ax] - this->Lo[ax];
          d = std::min(d, this->BallDistance(s, q[0], q[1], q[2]));
        }
        phi->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu] = static_cast<float>(d - this->InitialRadius);
        ballMask->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu] = d <= this->InitialRadius ? 1 : 0;
      }
    typename MaskImage<2>::Pointer mask;
    try
    {
      double slo = tlo, shi = thi;
      if (this->P.AdaptiveSliceStatistics && this->P.AutomaticThresholds)
      {
        // This slice's own seeds set its interval (the pooled one spans every level of
        // enhancement met along the structure).
        double m = 0, d = 0;
        for (size_t sd : entry.second)
        {
          m += this->SeedStats[sd].first;
          d = std::max(d, this->SeedStats[sd].second);
        }
        Window(m / entry.second.size(), d, this->P, slo, shi);
      }
      mask = Evolve<2>(sliceFeature(s0), phi, slo, shi, lsp, iterations2, nullptr, &this->Elapsed);
      KeepOverlapping<2>(mask, ballMask);
      if (this->P.AdaptiveSliceStatistics && this->P.AutomaticThresholds && this->P.RefineToHalfContrast)
      {
        mask = RefineSection(sliceFeature(s0), mask, slo, shi, lsp, iterations2);
        KeepOverlapping<2>(mask, ballMask);
      }
    }
    catch (const itk::ExceptionObject& e)
    {
      this->Error = e.GetDescription();
      return false;
    }
    auto store = [&](const MaskImage<2>* m, int is) {
      for (int iv = 0; iv < nv; ++iv)
        for (int iu = 0; iu < nu; ++iu)
          if (m->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu])
            this->InsideMask[this->AtSlice(iu, iv, is)] = 1;
      done[is] = 1;
    };
    const size_t area0 = Count<2>(mask);
    if (area0 * pixelArea < this->P.MinimumSliceArea)
      continue;
    store(mask, s0);
    for (int dir : { -1, 1 })
    {
      typename MaskImage<2>::Pointer previous = mask;
      FloatImage<2>::Pointer previousFeature = sliceFeature(s0);
      size_t previousArea = area0;
      for (int is = s0 + dir; is >= 0 && is < ns && !done[is]; is += dir)
      {
        const MaskImage<2>::Pointer start = Eroded(previous);
        typename MaskImage<2>::Pointer next;
        const FloatImage<2>::Pointer feature2 = sliceFeature(is);
        try
        {
          double slo = tlo, shi = thi;
          if (this->P.AdaptiveSliceStatistics && this->P.AutomaticThresholds)
          {
            // Follow the structure: the interval of this slice comes from the section
            // found in the previous one (contrast changes along a vessel).
            double m, d;
            if (MaskedStatistics(start, previousFeature, static_cast<size_t>(nu) * nv, m, d))
              Window(m, d, this->P, slo, shi);
          }
          next = Evolve<2>(feature2, SignedDistance<2>(start), slo, shi, lsp, iterations2, nullptr, &this->Elapsed);
          if (this->P.AdaptiveSliceStatistics && this->P.AutomaticThresholds && this->P.RefineToHalfContrast)
          {
            KeepOverlapping<2>(next, previous);
            next = RefineSection(feature2, next, slo, shi, lsp, iterations2);
          }
        }
        catch (const itk::ExceptionObject& e)
        {
          this->Error = e.GetDescription();
          return false;
        }
        KeepOverlapping<2>(next, previous);
        const size_t area = Count<2>(next);
        if (this->Ends(area, previousArea, pixelArea))
          break;
        store(next, is);
        previous = next;
        previousFeature = feature2;
        previousArea = area;
        if ((this->Abort && this->Abort()))
          return false;
      }
      this->Report((0.15 + 0.85 * started / bySlice.size()));
    }
  }
  return true;
}
