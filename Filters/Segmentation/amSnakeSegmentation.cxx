#include "amSnakeSegmentation.h"

#include "amInputCheck.h"
#include "amPolarContour.h"
#include "amProvenance.h"
#include "amThreading.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryErodeImageFilter.h>
#include <itkConnectedComponentImageFilter.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>
#include <itkSmoothingRecursiveGaussianImageFilter.h>
#include <itkThresholdSegmentationLevelSetImageFilter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

vtkStandardNewMacro(amSnakeSegmentation);

namespace
{
template <unsigned D>
using FloatImage = itk::Image<float, D>;
template <unsigned D>
using MaskImage = itk::Image<unsigned char, D>;

struct LevelSetParameters
{
  double Propagation, Curvature, Edge, RMS;
};

// Evolve a threshold level set from phi0 (negative inside) on 'feature'; returns the inside mask.
template <unsigned D>
typename MaskImage<D>::Pointer Evolve(FloatImage<D>* feature, FloatImage<D>* phi0, double lo, double hi,
  const LevelSetParameters& p, int iterations, const std::function<void(double)>& progress)
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
  ls->Update();
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

template <unsigned D>
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

template <unsigned D>
size_t Count(const MaskImage<D>* m)
{
  const size_t n = m->GetLargestPossibleRegion().GetNumberOfPixels();
  return static_cast<size_t>(std::count(m->GetBufferPointer(), m->GetBufferPointer() + n, 1));
}

// Keep the connected components of 'mask' that overlap 'reference'.
template <unsigned D>
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

// Slice-by-slice refinement: move the interval's edge that faces the section's surroundings
// half-way between the section's mean and that of a ring 2..4 pixels outside it, and evolve
// again from the section. Returns the refined mask (or the input when nothing changes).
MaskImage<2>::Pointer RefineSection(FloatImage<2>* feature, MaskImage<2>* section, double& lo, double& hi,
  const LevelSetParameters& p, int iterations)
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

struct Seed
{
  double Index[3]; // continuous index in the input image
  int Label;
};
}

amSnakeSegmentation::amSnakeSegmentation()
  : Mode(ThreeD)
  , SliceAxis(2)
  , SeedLabel(1)
  , SeedLabelArrayName(nullptr)
  , SmoothingSigma(1.0)
  , SeedRadius(3.0)
  , AutomaticThresholds(true)
  , IntensityTolerance(3.0)
  , MinimumIntensityWindow(100.0)
  , LowerThreshold(100.0)
  , UpperThreshold(600.0)
  , PropagationScaling(1.0)
  , CurvatureScaling(1.0)
  , EdgeWeight(0.0)
  , NumberOfIterations(800)
  , MaximumRMSError(0.002)
  , MaximumDistance(150.0)
  , MaximumAreaChange(2.0)
  , MinimumSliceArea(4.0)
  , AllowAirSeeds(false)
  , RefineToHalfContrast(true)
  , AdaptiveSliceStatistics(false)
  , ContourModel(LevelSet)
  , OutsideThreshold(-30.0)
  , EdgeContrast(40.0)
  , MaximumRadius(30.0)
  , MaximumGrowth(2.0)
  , AreaCost(0.4)
  , MinimumSectionContrast(0.5)
{
  amThreading::Initialize();
  this->SetNumberOfInputPorts(2);
  this->SetSeedLabelArrayName("Label");
}

amSnakeSegmentation::~amSnakeSegmentation()
{
  this->SetSeedLabelArrayName(nullptr);
}

void amSnakeSegmentation::AddSeed(double x, double y, double z, double label)
{
  this->Seeds.insert(this->Seeds.end(), { x, y, z, label });
  this->Modified();
}

void amSnakeSegmentation::RemoveAllSeeds()
{
  if (!this->Seeds.empty())
  {
    this->Seeds.clear();
    this->Modified();
  }
}

int amSnakeSegmentation::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int amSnakeSegmentation::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(0), VTK_UNSIGNED_CHAR, 1);
  return 1;
}

int amSnakeSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPointSet* seedSet = vtkPointSet::GetData(inputVector[1], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  int dims[3], extent[6];
  input->GetDimensions(dims);
  input->GetExtent(extent);
  const double* spacing = input->GetSpacing();

  // Gather seeds, in order; the order of first appearance of a label is its precedence.
  std::vector<Seed> seeds;
  auto addSeed = [&](const double x[3], int label) -> bool {
    if (label < 1 || label > 255)
    {
      vtkErrorMacro("Seed (" << x[0] << ", " << x[1] << ", " << x[2] << ") has label " << label
                             << "; labels are 1..255.");
      return false;
    }
    Seed s;
    input->TransformPhysicalPointToContinuousIndex(x, s.Index);
    for (int a = 0; a < 3; ++a)
    {
      s.Index[a] -= extent[2 * a];
      if (s.Index[a] < -0.5 || s.Index[a] > dims[a] - 0.5)
      {
        double b[6];
        input->GetBounds(b);
        vtkErrorMacro("Seed (" << x[0] << ", " << x[1] << ", " << x[2] << ") for label " << label
                               << " is outside the image (bounds " << b[0] << ".." << b[1] << ", " << b[2] << ".."
                               << b[3] << ", " << b[4] << ".." << b[5] << " mm).");
        return false;
      }
    }
    s.Label = label;
    seeds.push_back(s);
    return true;
  };
  for (size_t i = 0; i < this->Seeds.size(); i += 4)
  {
    const double l = this->Seeds[i + 3];
    if (l != std::floor(l))
    {
      vtkErrorMacro("Seed " << i / 4 << " has label " << l << "; labels are whole numbers 1..255.");
      return 0;
    }
    if (!addSeed(&this->Seeds[i], static_cast<int>(l)))
      return 0;
  }
  if (seedSet)
  {
    vtkDataArray* labels = this->SeedLabelArrayName ? seedSet->GetPointData()->GetArray(this->SeedLabelArrayName) : nullptr;
    for (vtkIdType i = 0; i < seedSet->GetNumberOfPoints(); ++i)
    {
      double x[3];
      seedSet->GetPoint(i, x);
      if (!addSeed(x, labels ? static_cast<int>(labels->GetComponent(i, 0)) : this->SeedLabel))
        return 0;
    }
  }
  if (seeds.empty())
  {
    vtkErrorMacro("No seeds: add seeds with AddSeed(x, y, z, label) or connect a point set to input port 1.");
    return 0;
  }
  if (this->ContourModel == Polar && this->Mode != SliceBySlice)
  {
    vtkErrorMacro("ContourModel Polar contours sections one slice at a time: set Mode to SliceBySlice.");
    return 0;
  }
  std::vector<int> order;
  for (const Seed& s : seeds)
    if (std::find(order.begin(), order.end(), s.Label) == order.end())
      order.push_back(s.Label);

  double range[2];
  scalars->GetRange(range, 0);
  if (!std::isfinite(range[0]) || !std::isfinite(range[1]))
  {
    vtkErrorMacro("The input image has non-finite values.");
    return 0;
  }

  vtkNew<vtkUnsignedCharArray> labelArray;
  labelArray->SetName("Labels");
  labelArray->SetNumberOfTuples(input->GetNumberOfPoints());
  labelArray->FillValue(0);
  unsigned char* out = labelArray->GetPointer(0);
  vtkNew<vtkDoubleArray> thresholds;
  thresholds->SetName("Thresholds");
  thresholds->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> volumes;
  volumes->SetName("SegmentedVolumes");
  volumes->SetNumberOfComponents(2);
  const LevelSetParameters lsp{ this->PropagationScaling, this->CurvatureScaling, this->EdgeWeight,
    this->MaximumRMSError };
  const double voxelVolume = spacing[0] * spacing[1] * spacing[2];
  // The initial contour must span a few voxels, or curvature collapses it before it can grow.
  const double initialRadius =
    std::max(this->SeedRadius, 2.5 * std::max(spacing[0], std::max(spacing[1], spacing[2])));

  for (size_t li = 0; li < order.size(); ++li)
  {
    const int label = order[li];
    const double p0 = static_cast<double>(li) / order.size(), p1 = static_cast<double>(li + 1) / order.size();
    std::vector<const Seed*> mine;
    for (const Seed& s : seeds)
      if (s.Label == label)
        mine.push_back(&s);
    // 1. Region of interest around the seeds.
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      double mn = 1e300, mx = -1e300;
      for (const Seed* s : mine)
      {
        mn = std::min(mn, s->Index[a]);
        mx = std::max(mx, s->Index[a]);
      }
      const double margin = this->MaximumDistance / spacing[a];
      lo[a] = std::max(0, static_cast<int>(std::floor(mn - margin)));
      hi[a] = std::min(dims[a] - 1, static_cast<int>(std::ceil(mx + margin)));
    }
    const int rd[3] = { hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1 };
    auto roi = FloatImage<3>::New();
    FloatImage<3>::RegionType region;
    FloatImage<3>::SizeType size = { { static_cast<itk::SizeValueType>(rd[0]), static_cast<itk::SizeValueType>(rd[1]),
      static_cast<itk::SizeValueType>(rd[2]) } };
    region.SetSize(size);
    roi->SetRegions(region);
    FloatImage<3>::SpacingType sp;
    for (int a = 0; a < 3; ++a)
      sp[a] = spacing[a];
    roi->SetSpacing(sp);
    roi->Allocate();
    float* rv = roi->GetBufferPointer();
    vtkSMPTools::For(0, rd[2], [&](vtkIdType k0, vtkIdType k1) {
      for (vtkIdType k = k0; k < k1; ++k)
        for (int j = 0; j < rd[1]; ++j)
          for (int i = 0; i < rd[0]; ++i)
          {
            const vtkIdType id = (static_cast<vtkIdType>(k + lo[2]) * dims[1] + (j + lo[1])) * dims[0] + (i + lo[0]);
            rv[(static_cast<size_t>(k) * rd[1] + j) * rd[0] + i] = static_cast<float>(scalars->GetComponent(id, 0));
          }
    });
    FloatImage<3>::Pointer feature = roi;
    if (this->SmoothingSigma > 0)
    {
      auto smooth = itk::SmoothingRecursiveGaussianImageFilter<FloatImage<3>, FloatImage<3>>::New();
      smooth->SetInput(roi);
      smooth->SetSigma(this->SmoothingSigma);
      smooth->Update();
      feature = smooth->GetOutput();
    }
    const float* fv = feature->GetBufferPointer();
    this->UpdateProgress(p0 + 0.1 * (p1 - p0));

    // 2. Intensity statistics in the seed balls; the initial contour is their union.
    auto ballDistance = [&](const Seed* s, double i, double j, double k) {
      const double dx = (i + lo[0] - s->Index[0]) * spacing[0], dy = (j + lo[1] - s->Index[1]) * spacing[1],
                   dz = (k + lo[2] - s->Index[2]) * spacing[2];
      return std::sqrt(dx * dx + dy * dy + dz * dz);
    };
    double sum = 0, sum2 = 0;
    long count = 0;
    std::map<const Seed*, std::pair<double, double>> seedStats; // mean, sd of each ball
    for (const Seed* s : mine)
    {
      const int r[3] = { static_cast<int>(std::ceil(this->SeedRadius / spacing[0])),
        static_cast<int>(std::ceil(this->SeedRadius / spacing[1])),
        static_cast<int>(std::ceil(this->SeedRadius / spacing[2])) };
      const int c[3] = { static_cast<int>(std::lround(s->Index[0])) - lo[0],
        static_cast<int>(std::lround(s->Index[1])) - lo[1], static_cast<int>(std::lround(s->Index[2])) - lo[2] };
      double ssum = 0, ssum2 = 0;
      long scount = 0;
      for (int k = std::max(0, c[2] - r[2]); k <= std::min(rd[2] - 1, c[2] + r[2]); ++k)
        for (int j = std::max(0, c[1] - r[1]); j <= std::min(rd[1] - 1, c[1] + r[1]); ++j)
          for (int i = std::max(0, c[0] - r[0]); i <= std::min(rd[0] - 1, c[0] + r[0]); ++i)
            if (ballDistance(s, i, j, k) <= this->SeedRadius)
            {
              const double v = fv[(static_cast<size_t>(k) * rd[1] + j) * rd[0] + i];
              sum += v;
              sum2 += v * v;
              ssum += v;
              ssum2 += v * v;
              ++count;
              ++scount;
            }
      if (scount == 0)
      {
        const double v = fv[(static_cast<size_t>(c[2]) * rd[1] + c[1]) * rd[0] + c[0]];
        sum += v;
        sum2 += v * v;
        ssum = v;
        ssum2 = v * v;
        scount = 1;
        ++count;
      }
      seedStats[s] = { ssum / scount,
        std::sqrt(std::max(0.0, ssum2 / scount - (ssum / scount) * (ssum / scount))) };
      if (!this->AllowAirSeeds && range[0] <= -900.0 && ssum / scount < -950.0)
      {
        double w[3];
        input->TransformContinuousIndexToPhysicalPoint(s->Index[0] + extent[0], s->Index[1] + extent[2],
          s->Index[2] + extent[4], w);
        vtkErrorMacro("Seed (" << w[0] << ", " << w[1] << ", " << w[2] << ") for label " << label
                               << " lies in air (mean " << ssum / scount
                               << " HU around it); move it into the organ, or set AllowAirSeeds.");
        return 0;
      }
    }
    const double mean = sum / count, sd = std::sqrt(std::max(0.0, sum2 / count - mean * mean));
    double tlo = this->LowerThreshold, thi = this->UpperThreshold;
    if (this->AutomaticThresholds)
    {
      const double half = std::max(this->IntensityTolerance * sd, this->MinimumIntensityWindow);
      tlo = mean - half;
      thi = mean + half;
    }
    auto progress = [&](double base, double span) {
      return [this, base, span](double f) { this->UpdateProgress(base + span * f); };
    };
    std::vector<unsigned char> inside(static_cast<size_t>(rd[0]) * rd[1] * rd[2], 0);
    // One evolution with the interval [tlo, thi]; 'initial' (3-D mode) restarts from a mask.
    auto run = [&](double tlo, double thi, MaskImage<3>* initial, double pa, double pb) -> bool {
      std::fill(inside.begin(), inside.end(), 0);
      if (this->Mode == ThreeD)
      {
        auto phi = FloatImage<3>::New();
        phi->SetRegions(region);
        phi->SetSpacing(sp);
        phi->Allocate();
        float* pv = phi->GetBufferPointer();
        vtkSMPTools::For(0, rd[2], [&](vtkIdType k0, vtkIdType k1) {
          for (vtkIdType k = k0; k < k1; ++k)
            for (int j = 0; j < rd[1]; ++j)
              for (int i = 0; i < rd[0]; ++i)
              {
                double d = 1e30;
                for (const Seed* s : mine)
                  d = std::min(d, ballDistance(s, i, j, static_cast<double>(k)));
                pv[(static_cast<size_t>(k) * rd[1] + j) * rd[0] + i] = static_cast<float>(d - initialRadius);
              }
        });
        if (initial)
          phi = SignedDistance<3>(initial);
        try
        {
          auto mask = Evolve<3>(feature, phi, tlo, thi, lsp, initial ? std::min(200, this->NumberOfIterations)
                                                                      : this->NumberOfIterations,
            progress(pa, pb));
          std::copy(mask->GetBufferPointer(), mask->GetBufferPointer() + inside.size(), inside.begin());
        }
        catch (const itk::ExceptionObject& e)
        {
          vtkErrorMacro("Level-set evolution failed for label " << label << ": " << e.GetDescription());
          return false;
        }
      }
      else
      {
        // Slice-by-slice propagation along SliceAxis.
        const int ax = this->SliceAxis, u = ax == 0 ? 1 : 0, v = ax == 2 ? 1 : 2;
        const int nu = rd[u], nv = rd[v], ns = rd[ax];
        FloatImage<2>::RegionType region2;
        FloatImage<2>::SizeType size2 = { { static_cast<itk::SizeValueType>(nu), static_cast<itk::SizeValueType>(nv) } };
        region2.SetSize(size2);
        FloatImage<2>::SpacingType sp2;
        sp2[0] = spacing[u];
        sp2[1] = spacing[v];
        const double pixelArea = spacing[u] * spacing[v];
        auto at = [&](int iu, int iv, int is) {
          int ijk[3];
          ijk[u] = iu;
          ijk[v] = iv;
          ijk[ax] = is;
          return (static_cast<size_t>(ijk[2]) * rd[1] + ijk[1]) * rd[0] + ijk[0];
        };
        auto sliceFeature = [&](int is) {
          auto img = FloatImage<2>::New();
          img->SetRegions(region2);
          img->SetSpacing(sp2);
          img->Allocate();
          for (int iv = 0; iv < nv; ++iv)
            for (int iu = 0; iu < nu; ++iu)
              img->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu] = fv[at(iu, iv, is)];
          return img;
        };
        auto newMask = [&]() {
          auto m = MaskImage<2>::New();
          m->SetRegions(region2);
          m->SetSpacing(sp2);
          m->Allocate();
          m->FillBuffer(0);
          return m;
        };
        // The stopping rule of a propagation: the section vanished, or changed abruptly (the
        // structure ended, or merged with another one).
        const auto ends = [&](size_t area, size_t previousArea) {
          return area * pixelArea < this->MinimumSliceArea || area > this->MaximumAreaChange * previousArea ||
            area * this->MaximumAreaChange < previousArea;
        };
        if (this->ContourModel == Polar)
        {
          // One track per seed: a star-shaped snake in the seed's slice, then slice after slice
          // around the last section's centroid, the last contour as prior.
          amPolarContour::Parameters pp;
          pp.OutsideThreshold = this->OutsideThreshold;
          pp.EdgeContrast = this->EdgeContrast;
          pp.MaximumRadius = this->MaximumRadius;
          pp.MaximumGrowth = this->MaximumGrowth;
          pp.AreaCost = this->AreaCost;
          std::vector<float> slice(static_cast<size_t>(nu) * nv);
          const auto load = [&](int is) {
            for (int iv = 0; iv < nv; ++iv)
              for (int iu = 0; iu < nu; ++iu)
                slice[static_cast<size_t>(iv) * nu + iu] = fv[at(iu, iv, is)];
          };
          const amPolarContour contour(slice.data(), nu, nv, spacing[u], spacing[v]);
          std::vector<unsigned char> section(slice.size()), previous;
          // Pixels of the section in slice is, and how many of them earlier tracks already have.
          const auto measure = [&](int is, size_t& area, size_t& taken) {
            area = taken = 0;
            for (int iv = 0; iv < nv; ++iv)
              for (int iu = 0; iu < nu; ++iu)
                if (section[static_cast<size_t>(iv) * nu + iu])
                {
                  ++area;
                  taken += inside[at(iu, iv, is)];
                }
          };
          const auto store = [&](int is) {
            for (int iv = 0; iv < nv; ++iv)
              for (int iu = 0; iu < nu; ++iu)
                if (section[static_cast<size_t>(iv) * nu + iu])
                  inside[at(iu, iv, is)] = 1;
          };
          size_t started = 0;
          for (const Seed* sd : mine)
          {
            ++started;
            const int s0 = std::min(ns - 1, std::max(0, static_cast<int>(std::lround(sd->Index[ax])) - lo[ax]));
            const double cu = sd->Index[u] - lo[u], cv = sd->Index[v] - lo[v];
            load(s0);
            std::fill(section.begin(), section.end(), 0);
            contour.Fill(cu, cv, contour.Find(cu, cv, {}, pp), section.data());
            size_t area0, taken;
            measure(s0, area0, taken);
            // A seed whose section earlier tracks already cover (90 %) adds nothing; one that
            // covers more (where a vessel's section is not star-shaped, as in the arch) goes on.
            if (area0 == 0 || area0 * pixelArea < this->MinimumSliceArea || 10 * taken >= 9 * area0)
              continue;
            store(s0);
            const std::vector<unsigned char> seedSection = section;
            // The section's mean contrast above OutsideThreshold; the seed's sets the scale.
            const auto contrast = [&]() {
              double sum = 0;
              size_t c = 0;
              for (size_t q = 0; q < section.size(); ++q)
                if (section[q])
                {
                  sum += slice[q];
                  ++c;
                }
              return c ? sum / c - this->OutsideThreshold : 0.0;
            };
            const double seedContrast = contrast();
            for (int dir : { -1, 1 })
            {
              previous = seedSection;
              size_t previousArea = area0;
              for (int is = s0 + dir; is >= 0 && is < ns; is += dir)
              {
                double mu = 0, mv = 0;
                size_t c = 0;
                for (int iv = 0; iv < nv; ++iv)
                  for (int iu = 0; iu < nu; ++iu)
                    if (previous[static_cast<size_t>(iv) * nu + iu])
                    {
                      mu += iu;
                      mv += iv;
                      ++c;
                    }
                mu /= c;
                mv /= c;
                const std::vector<double> prior = contour.RadiiOf(previous.data(), mu, mv, pp.MaximumRadius);
                load(is);
                std::fill(section.begin(), section.end(), 0);
                contour.Fill(mu, mv, contour.Find(mu, mv, prior, pp), section.data());
                size_t area;
                measure(is, area, taken);
                // The stopping rule, or the section no longer looks like the structure (a heart's
                // section entering the liver).
                if (ends(area, previousArea) || contrast() < this->MinimumSectionContrast * seedContrast)
                  break;
                store(is);
                if (2 * taken > area)
                  break; // met another track
                previous = section;
                previousArea = area;
                if (this->GetAbortExecute())
                  return false;
              }
            }
            this->UpdateProgress(p0 + (p1 - p0) * (0.15 + 0.85 * started / mine.size()));
          }
          return true;
        }
        std::vector<char> done(static_cast<size_t>(ns), 0);
        std::map<int, std::vector<const Seed*>> bySlice;
        for (const Seed* s : mine)
          bySlice[std::min(ns - 1, std::max(0, static_cast<int>(std::lround(s->Index[ax])) - lo[ax]))].push_back(s);
        const int iterations2 = std::min(this->NumberOfIterations, 400);
        size_t started = 0;
        for (const auto& entry : bySlice)
        {
          const int s0 = entry.first;
          ++started;
          if (done[s0])
            continue;
          // The seed slice: balls cut by the slice.
          auto phi = FloatImage<2>::New();
          phi->SetRegions(region2);
          phi->SetSpacing(sp2);
          phi->Allocate();
          auto ballMask = newMask();
          for (int iv = 0; iv < nv; ++iv)
            for (int iu = 0; iu < nu; ++iu)
            {
              int ijk[3];
              ijk[u] = iu;
              ijk[v] = iv;
              ijk[ax] = s0;
              double d = 1e30;
              for (const Seed* s : entry.second)
              {
                double q[3] = { static_cast<double>(ijk[0]), static_cast<double>(ijk[1]), static_cast<double>(ijk[2]) };
                q[ax] = s->Index[ax] - lo[ax];
                d = std::min(d, ballDistance(s, q[0], q[1], q[2]));
              }
              phi->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu] = static_cast<float>(d - initialRadius);
              ballMask->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu] = d <= initialRadius ? 1 : 0;
            }
          typename MaskImage<2>::Pointer mask;
          try
          {
            double slo = tlo, shi = thi;
            if (this->AdaptiveSliceStatistics && this->AutomaticThresholds)
            {
              // This slice's own seeds set its interval (the pooled one spans every level of
              // enhancement met along the structure).
              double m = 0, d = 0;
              for (const Seed* sd : entry.second)
              {
                m += seedStats[sd].first;
                d = std::max(d, seedStats[sd].second);
              }
              m /= entry.second.size();
              const double half = std::max(this->IntensityTolerance * d, this->MinimumIntensityWindow);
              slo = m - half;
              shi = m + half;
            }
            mask = Evolve<2>(sliceFeature(s0), phi, slo, shi, lsp, iterations2, nullptr);
            KeepOverlapping<2>(mask, ballMask);
            if (this->AdaptiveSliceStatistics && this->AutomaticThresholds && this->RefineToHalfContrast)
            {
              mask = RefineSection(sliceFeature(s0), mask, slo, shi, lsp, iterations2);
              KeepOverlapping<2>(mask, ballMask);
            }
          }
          catch (const itk::ExceptionObject& e)
          {
            vtkErrorMacro("Level-set evolution failed for label " << label << ": " << e.GetDescription());
            return false;
          }
          auto store = [&](const MaskImage<2>* m, int is) {
            for (int iv = 0; iv < nv; ++iv)
              for (int iu = 0; iu < nu; ++iu)
                if (m->GetBufferPointer()[static_cast<size_t>(iv) * nu + iu])
                  inside[at(iu, iv, is)] = 1;
            done[is] = 1;
          };
          const size_t area0 = Count<2>(mask);
          if (area0 * pixelArea < this->MinimumSliceArea)
            continue;
          store(mask, s0);
          for (int dir : { -1, 1 })
          {
            typename MaskImage<2>::Pointer previous = mask;
            FloatImage<2>::Pointer previousFeature = sliceFeature(s0);
            size_t previousArea = area0;
            for (int is = s0 + dir; is >= 0 && is < ns && !done[is]; is += dir)
            {
              auto erode = itk::BinaryErodeImageFilter<MaskImage<2>, MaskImage<2>,
                itk::BinaryBallStructuringElement<unsigned char, 2>>::New();
              itk::BinaryBallStructuringElement<unsigned char, 2> ball;
              ball.SetRadius(1);
              ball.CreateStructuringElement();
              erode->SetKernel(ball);
              erode->SetInput(previous);
              erode->SetForegroundValue(1);
              erode->Update();
              MaskImage<2>::Pointer start = previous;
              if (Count<2>(erode->GetOutput()) > 0)
                start = erode->GetOutput();
              typename MaskImage<2>::Pointer next;
              const FloatImage<2>::Pointer feature2 = sliceFeature(is);
              try
              {
                double slo = tlo, shi = thi;
                if (this->AdaptiveSliceStatistics && this->AutomaticThresholds)
                {
                  // Follow the structure: the interval of this slice comes from the section
                  // found in the previous one (contrast changes along a vessel).
                  const FloatImage<2>* prevFeature = previousFeature;
                  double a = 0, a2 = 0;
                  long c = 0;
                  for (size_t q = 0; q < static_cast<size_t>(nu) * nv; ++q)
                    if (start->GetBufferPointer()[q])
                    {
                      const double f = prevFeature->GetBufferPointer()[q];
                      a += f;
                      a2 += f * f;
                      ++c;
                    }
                  if (c > 0)
                  {
                    const double m = a / c, d = std::sqrt(std::max(0.0, a2 / c - m * m));
                    const double half = std::max(this->IntensityTolerance * d, this->MinimumIntensityWindow);
                    slo = m - half;
                    shi = m + half;
                  }
                }
                next = Evolve<2>(feature2, SignedDistance<2>(start), slo, shi, lsp, iterations2, nullptr);
                if (this->AdaptiveSliceStatistics && this->AutomaticThresholds && this->RefineToHalfContrast)
                {
                  KeepOverlapping<2>(next, previous);
                  next = RefineSection(feature2, next, slo, shi, lsp, iterations2);
                }
              }
              catch (const itk::ExceptionObject& e)
              {
                vtkErrorMacro("Level-set evolution failed for label " << label << ": " << e.GetDescription());
                return false;
              }
              KeepOverlapping<2>(next, previous);
              const size_t area = Count<2>(next);
              if (ends(area, previousArea))
                break;
              store(next, is);
              previous = next;
              previousFeature = feature2;
              previousArea = area;
              if (this->GetAbortExecute())
                return false;
            }
            this->UpdateProgress(p0 + (p1 - p0) * (0.15 + 0.85 * started / bySlice.size()));
          }
        }
      }

      return true;
    };
    if (!run(tlo, thi, nullptr, p0 + 0.15 * (p1 - p0), 0.55 * (p1 - p0)))
      return 0;
    // Refinement: the contour should stop half-way between the organ's intensity and that of
    // its surroundings (where partial volume puts the true boundary), not at the edge of the
    // statistical interval. Sample a 2-voxel shell outside (beyond the smoothing's blur), move the facing threshold there
    // (never narrowing the interval) and evolve again.
    if (this->ContourModel == Polar)
    {
      tlo = this->OutsideThreshold;
      thi = range[1];
    }
    else if (this->AutomaticThresholds && this->RefineToHalfContrast)
    {
      auto mask3 = MaskImage<3>::New();
      mask3->SetRegions(region);
      mask3->SetSpacing(sp);
      mask3->Allocate();
      std::copy(inside.begin(), inside.end(), mask3->GetBufferPointer());
      auto dist = SignedDistance<3>(mask3);
      const float* dv = dist->GetBufferPointer();
      // Beyond the blur of the smoothing, two voxels thick.
      const double voxel = std::max(spacing[0], std::max(spacing[1], spacing[2]));
      const double shellIn = std::max(2.0 * voxel, 2.0 * this->SmoothingSigma), shellOut = shellIn + 2.0 * voxel;
      double osum = 0;
      long ocount = 0;
      for (size_t i = 0; i < inside.size(); ++i)
        if (dv[i] > shellIn && dv[i] <= shellOut)
        {
          osum += fv[i];
          ++ocount;
        }
      if (ocount > 0 && std::count(inside.begin(), inside.end(), 1) > 0)
      {
        const double outside = osum / ocount, mid = 0.5 * (mean + outside);
        bool changed = false;
        if (outside < mean && mid < tlo)
        {
          tlo = mid;
          changed = true;
        }
        else if (outside > mean && mid > thi)
        {
          thi = mid;
          changed = true;
        }
        if (changed && !run(tlo, thi, this->Mode == ThreeD ? mask3.GetPointer() : nullptr, p0 + 0.7 * (p1 - p0),
              0.3 * (p1 - p0)))
          return 0;
      }
    }
    thresholds->InsertNextTuple3(label, tlo, thi);

    // Paste into the label map: earlier labels keep their voxels.
    size_t voxels = 0;
    for (int k = 0; k < rd[2]; ++k)
      for (int j = 0; j < rd[1]; ++j)
        for (int i = 0; i < rd[0]; ++i)
          if (inside[(static_cast<size_t>(k) * rd[1] + j) * rd[0] + i])
          {
            const vtkIdType id = (static_cast<vtkIdType>(k + lo[2]) * dims[1] + (j + lo[1])) * dims[0] + (i + lo[0]);
            if (out[id] == 0)
            {
              out[id] = static_cast<unsigned char>(label);
              ++voxels;
            }
          }
    volumes->InsertNextTuple2(label, voxels * voxelVolume);
    if (voxels == 0)
      vtkWarningMacro("Label " << label << ": the contour vanished (no voxel in [" << tlo << ", " << thi
                               << "] around its seeds, or every voxel already taken by an earlier label).");
    this->UpdateProgress(p1);
  }

  output->CopyStructure(input);
  output->GetPointData()->SetScalars(labelArray);
  output->GetFieldData()->AddArray(thresholds);
  output->GetFieldData()->AddArray(volumes);
  std::ostringstream params;
  params << "Mode=" << (this->Mode == ThreeD ? "ThreeD" : "SliceBySlice") << " Seeds=" << seeds.size()
         << " SmoothingSigma=" << this->SmoothingSigma << " SeedRadius=" << this->SeedRadius
         << " AutomaticThresholds=" << this->AutomaticThresholds << " IntensityTolerance=" << this->IntensityTolerance
         << " MinimumIntensityWindow=" << this->MinimumIntensityWindow << " Propagation=" << this->PropagationScaling
         << " Curvature=" << this->CurvatureScaling << " EdgeWeight=" << this->EdgeWeight
         << " Iterations=" << this->NumberOfIterations << " MaximumDistance=" << this->MaximumDistance
         << " ContourModel=" << (this->ContourModel == Polar ? "Polar" : "LevelSet");
  if (this->ContourModel == Polar)
    params << " OutsideThreshold=" << this->OutsideThreshold << " EdgeContrast=" << this->EdgeContrast
           << " MaximumRadius=" << this->MaximumRadius << " MaximumGrowth=" << this->MaximumGrowth
           << " AreaCost=" << this->AreaCost << " MinimumSectionContrast=" << this->MinimumSectionContrast;
  amProvenance::Record(output, input, "amSnakeSegmentation", params.str());
  return 1;
}

void amSnakeSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Seeds: " << this->Seeds.size() / 4 << "\n";
  os << indent << "SmoothingSigma: " << this->SmoothingSigma << " mm\n";
  os << indent << "SeedRadius: " << this->SeedRadius << " mm\n";
  os << indent << "IntensityTolerance: " << this->IntensityTolerance << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "ContourModel: " << (this->ContourModel == Polar ? "Polar" : "LevelSet") << "\n";
  os << indent << "OutsideThreshold: " << this->OutsideThreshold << "\n";
  os << indent << "EdgeContrast: " << this->EdgeContrast << "\n";
  os << indent << "MaximumRadius: " << this->MaximumRadius << " mm\n";
  os << indent << "MaximumGrowth: " << this->MaximumGrowth << " mm\n";
  os << indent << "AreaCost: " << this->AreaCost << " per mm\n";
  os << indent << "MinimumSectionContrast: " << this->MinimumSectionContrast << "\n";
}
