/**
 * @file    amSnakeLevelSet.h
 * @brief   The level-set steps of the snake tracker (ITK): a threshold level set evolved from an
 *          initial contour, signed distances, component filtering and the half-contrast refinement
 *          of a section. Private to FiltersSegmentation; included by the tracker's sources only.
 */
#ifndef amSnakeLevelSet_h
#define amSnakeLevelSet_h

#include <itkConnectedComponentImageFilter.h>
#include <itkImageAlgorithm.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>
#include <itkThresholdSegmentationLevelSetImageFilter.h>

#include <algorithm>
#include <functional>
#include <set>

namespace amSnakeLevelSet
{
template<unsigned D>
using FloatImage = itk::Image<float, D>;
template<unsigned D>
using MaskImage = itk::Image<unsigned char, D>;

struct Parameters
{
  double Propagation, Curvature, Edge, RMS;
  bool StopOnStall = true; // see Evolve
};

/// The level-set weights and stops of a tracker's parameters (amSnakeTracker::Parameters).
template<typename TrackerParameters>
Parameters LevelSetParameters(const TrackerParameters& p)
{
  return { p.PropagationScaling, p.CurvatureScaling, p.EdgeWeight, p.MaximumRMSError, p.StopOnStall };
}

/// A 3-D ITK image of the given size and spacing, origin 0.
template<typename Image>
typename Image::Pointer NewImage(const int size[3], const double spacing[3])
{
  auto image = Image::New();
  typename Image::RegionType region;
  typename Image::SizeType s = { { static_cast<itk::SizeValueType>(size[0]), static_cast<itk::SizeValueType>(size[1]),
    static_cast<itk::SizeValueType>(size[2]) } };
  region.SetSize(s);
  image->SetRegions(region);
  typename Image::SpacingType sp;
  for (int a = 0; a < 3; ++a)
    sp[a] = spacing[a];
  image->SetSpacing(sp);
  image->Allocate();
  return image;
}

/// Iterations between two counts of the inside: the evolution stops when two counts in a row
/// are equal. Even: a front cycling between two states is compared with itself, and stops in the
/// state an even iteration limit would have ended in.
constexpr unsigned StallWindow = 20;

/// Evolve a threshold level set (ITK's ThresholdSegmentationLevelSetImageFilter) from phi0
/// (negative inside) on 'feature'; returns the inside mask. Besides ITK's own stop (the RMS
/// change under p.RMS), the evolution stops once the inside has kept its voxel count for
/// StallWindow iterations: on a noisy image the front settles into a cycle of two states with the
/// same inside whose RMS change stays above any useful bound, and would run to 'iterations'.
/// p.StopOnStall false leaves ITK's stops alone. 'elapsed' (may be null) is added the
/// iterations run.
template<unsigned D>
typename MaskImage<D>::Pointer Evolve(FloatImage<D>* feature, FloatImage<D>* phi0, double lo, double hi,
  const Parameters& p, int iterations, const std::function<void(double)>& progress, long long* elapsed = nullptr)
{
  using Filter = itk::ThresholdSegmentationLevelSetImageFilter<FloatImage<D>, FloatImage<D>>;
  auto ls = Filter::New();
  ls->SetInput(phi0);
  ls->SetFeatureImage(feature);
  ls->SetLowerThreshold(lo);
  ls->SetUpperThreshold(hi);
  ls->SetPropagationScaling(p.Propagation);
  ls->SetCurvatureScaling(p.Curvature);
  ls->SetEdgeWeight(p.Edge);
  ls->SetMaximumRMSError(p.RMS);
  ls->SetNumberOfIterations(iterations);
  if (progress)
    ls->AddObserver(itk::ProgressEvent(), [&](const itk::EventObject&) { progress(ls->GetProgress()); });
  size_t lastInside = 0;
  bool counted = false;
  ls->AddObserver(itk::IterationEvent(), [&](const itk::EventObject&) {
    const unsigned done = ls->GetElapsedIterations();
    if (!p.StopOnStall || done == 0 || done % StallWindow != 0)
      return;
    const float* phi = ls->GetOutput()->GetBufferPointer();
    const size_t n = ls->GetOutput()->GetLargestPossibleRegion().GetNumberOfPixels();
    const size_t inside = static_cast<size_t>(std::count_if(phi, phi + n, [](float v) { return v <= 0.0f; }));
    if (counted && inside == lastInside)
      ls->SetNumberOfIterations(done); // ITK's Halt() ends the loop at the next check
    lastInside = inside;
    counted = true;
  });
  ls->Update();
  if (elapsed)
    *elapsed += ls->GetElapsedIterations();
  auto mask = MaskImage<D>::New();
  mask->SetRegions(ls->GetOutput()->GetLargestPossibleRegion());
  mask->CopyInformation(ls->GetOutput());
  mask->Allocate();
  const float* phi = ls->GetOutput()->GetBufferPointer();
  unsigned char* m = mask->GetBufferPointer();
  const size_t n = ls->GetOutput()->GetLargestPossibleRegion().GetNumberOfPixels();
  for (size_t i = 0; i < n; ++i)
    m[i] = phi[i] <= 0.0f ? 1 : 0;
  return mask;
}

/// Signed distance (mm) to the mask's boundary, negative inside.
template<unsigned D>
typename FloatImage<D>::Pointer SignedDistance(MaskImage<D>* mask)
{
  auto dist = itk::SignedMaurerDistanceMapImageFilter<MaskImage<D>, FloatImage<D>>::New();
  dist->SetInput(mask);
  dist->SetUseImageSpacing(true);
  dist->SetSquaredDistance(false);
  dist->SetInsideIsPositive(false);
  dist->SetBackgroundValue(0);
  dist->Update();
  return dist->GetOutput();
}

/// SignedDistance computed only in the mask's bounding box grown by 'margin' voxels, and 'far'
/// (positive: outside) beyond it. Exact in the box, where every boundary voxel lies: enough for a
/// level set, which reads the distance only next to the contour, and for shells within 'margin'
/// voxels of it, on a region of interest much larger than the organ.
template<unsigned D>
typename FloatImage<D>::Pointer SignedDistanceNear(MaskImage<D>* mask, int margin, float far)
{
  using Index = typename MaskImage<D>::IndexType;
  const auto whole = mask->GetLargestPossibleRegion();
  Index lo, hi;
  for (unsigned a = 0; a < D; ++a)
  {
    lo[a] = whole.GetIndex(a) + static_cast<long>(whole.GetSize(a));
    hi[a] = whole.GetIndex(a) - 1;
  }
  itk::ImageRegionConstIteratorWithIndex<MaskImage<D>> in(mask, whole);
  for (; !in.IsAtEnd(); ++in)
    if (in.Get())
      for (unsigned a = 0; a < D; ++a)
      {
        lo[a] = std::min(lo[a], in.GetIndex()[a]);
        hi[a] = std::max(hi[a], in.GetIndex()[a]);
      }
  typename MaskImage<D>::RegionType box;
  bool all = true;
  for (unsigned a = 0; a < D; ++a)
  {
    const long first = std::max<long>(whole.GetIndex(a), lo[a] - margin);
    const long last = std::min<long>(whole.GetIndex(a) + static_cast<long>(whole.GetSize(a)) - 1, hi[a] + margin);
    box.SetIndex(a, first);
    box.SetSize(a, static_cast<itk::SizeValueType>(std::max<long>(0, last - first + 1)));
    all = all && box.GetSize(a) == whole.GetSize(a);
  }
  if (all)
    return SignedDistance<D>(mask);
  auto out = FloatImage<D>::New();
  out->SetRegions(whole);
  out->CopyInformation(mask);
  out->Allocate();
  out->FillBuffer(far);
  if (box.GetNumberOfPixels() == 0)
    return out; // an empty mask: outside everywhere
  auto sub = MaskImage<D>::New();
  sub->SetRegions(box);
  sub->CopyInformation(mask);
  sub->Allocate();
  itk::ImageAlgorithm::Copy(mask, sub.GetPointer(), box, box);
  auto dist = SignedDistance<D>(sub);
  itk::ImageAlgorithm::Copy(dist.GetPointer(), out.GetPointer(), box, box);
  return out;
}

/// The level set's starting function from a contour's inside: the signed distance next to the
/// contour (four voxels), five voxels beyond (the level set reads it only next to the contour).
inline FloatImage<3>::Pointer PhiFromMask(MaskImage<3>* mask)
{
  const auto& sp = mask->GetSpacing();
  const double voxel = std::max(sp[0], std::max(sp[1], sp[2]));
  return SignedDistanceNear<3>(mask, 4, static_cast<float>(5 * voxel));
}

template<unsigned D>
size_t Count(const MaskImage<D>* m)
{
  const size_t n = m->GetLargestPossibleRegion().GetNumberOfPixels();
  return static_cast<size_t>(std::count(m->GetBufferPointer(), m->GetBufferPointer() + n, 1));
}

/// Keep the connected components of 'mask' that overlap 'reference'.
template<unsigned D>
void KeepOverlapping(MaskImage<D>* mask, const MaskImage<D>* reference)
{
  using LabelImage = itk::Image<unsigned int, D>;
  auto cc = itk::ConnectedComponentImageFilter<MaskImage<D>, LabelImage>::New();
  cc->SetInput(mask);
  cc->SetFullyConnected(false);
  cc->Update();
  const unsigned* c = cc->GetOutput()->GetBufferPointer();
  const size_t n = mask->GetLargestPossibleRegion().GetNumberOfPixels();
  std::set<unsigned> keep;
  for (size_t i = 0; i < n; ++i)
    if (reference->GetBufferPointer()[i] && c[i])
      keep.insert(c[i]);
  unsigned char* m = mask->GetBufferPointer();
  for (size_t i = 0; i < n; ++i)
    m[i] = (c[i] && keep.count(c[i])) ? 1 : 0;
}

/// Slice-by-slice refinement: move the interval's edge that faces the section's surroundings
/// half-way between the section's mean and that of a ring 2..4 pixels outside it, and evolve
/// again from the section. Returns the refined mask (or the input when nothing changes).
inline MaskImage<2>::Pointer RefineSection(
  FloatImage<2>* feature, MaskImage<2>* section, double& lo, double& hi, const Parameters& p, int iterations)
{
  auto dist = SignedDistance<2>(section);
  const double px = std::max(feature->GetSpacing()[0], feature->GetSpacing()[1]);
  const size_t n = feature->GetLargestPossibleRegion().GetNumberOfPixels();
  const float* f = feature->GetBufferPointer();
  const float* d = dist->GetBufferPointer();
  double in = 0, out = 0;
  long ni = 0, no = 0;
  for (size_t i = 0; i < n; ++i)
  {
    if (section->GetBufferPointer()[i])
    {
      in += f[i];
      ++ni;
    }
    else if (d[i] > 2.0 * px && d[i] <= 4.0 * px)
    {
      out += f[i];
      ++no;
    }
  }
  if (!ni || !no)
    return section;
  const double mi = in / ni, mo = out / no, mid = 0.5 * (mi + mo);
  if (mo < mi && mid < lo)
    lo = mid;
  else if (mo > mi && mid > hi)
    hi = mid;
  else
    return section;
  auto refined = Evolve<2>(feature, dist, lo, hi, p, iterations, nullptr);
  KeepOverlapping<2>(refined, section);
  return refined;
}
}

#endif
