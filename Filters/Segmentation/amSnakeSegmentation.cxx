#include "amSnakeSegmentation.h"

#include "amConcurrentTasks.h"
#include "amInputCheck.h"
#include "amIntensityWindow.h"
#include "amProvenance.h"
#include "amSeedCompetition.h"
#include "amSnakeTracker.h"
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

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <sstream>

vtkStandardNewMacro(amSnakeSegmentation);

namespace
{
struct Seed
{
  double Index[3]; // continuous index in the input image
  int Label;
};

// The seeds, typed ones first, then the point set's, in order (the order of first appearance of
// a label is its precedence); false with 'why' for a label outside 1..255 or a seed outside the
// image.
bool GatherSeeds(vtkImageData* input, const std::vector<double>& typed, vtkPointSet* seedSet,
  const char* labelArrayName, int defaultLabel, std::vector<Seed>& seeds, std::string& why)
{
  int dims[3], extent[6];
  input->GetDimensions(dims);
  input->GetExtent(extent);
  std::ostringstream message;
  auto addSeed = [&](const double x[3], int label) -> bool {
    if (label < 1 || label > 255)
    {
      message << "Seed (" << x[0] << ", " << x[1] << ", " << x[2] << ") has label " << label << "; labels are 1..255.";
      why = message.str();
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
        message << "Seed (" << x[0] << ", " << x[1] << ", " << x[2] << ") for label " << label
                << " is outside the image (bounds " << b[0] << ".." << b[1] << ", " << b[2] << ".." << b[3] << ", "
                << b[4] << ".." << b[5] << " mm).";
        why = message.str();
        return false;
      }
    }
    s.Label = label;
    seeds.push_back(s);
    return true;
  };
  for (size_t i = 0; i < typed.size(); i += 4)
  {
    const double l = typed[i + 3];
    if (l != std::floor(l))
    {
      message << "Seed " << i / 4 << " has label " << l << "; labels are whole numbers 1..255.";
      why = message.str();
      return false;
    }
    if (!addSeed(&typed[i], static_cast<int>(l)))
      return false;
  }
  if (seedSet)
  {
    vtkDataArray* labels = labelArrayName ? seedSet->GetPointData()->GetArray(labelArrayName) : nullptr;
    for (vtkIdType i = 0; i < seedSet->GetNumberOfPoints(); ++i)
    {
      double x[3];
      seedSet->GetPoint(i, x);
      if (!addSeed(x, labels ? static_cast<int>(labels->GetComponent(i, 0)) : defaultLabel))
        return false;
    }
  }
  return true;
}

// The box of voxels within 'margin' mm of the seeds (continuous indices), inside the image.
void RegionAround(const std::vector<std::array<double, 3>>& seeds, double margin, const double spacing[3],
  const int dims[3], int lo[3], int size[3])
{
  for (int a = 0; a < 3; ++a)
  {
    double mn = 1e300, mx = -1e300;
    for (const auto& s : seeds)
    {
      mn = std::min(mn, s[a]);
      mx = std::max(mx, s[a]);
    }
    const double m = margin / spacing[a];
    lo[a] = std::max(0, static_cast<int>(std::floor(mn - m)));
    size[a] = std::min(dims[a] - 1, static_cast<int>(std::ceil(mx + m))) - lo[a] + 1;
  }
}

// The scan's values in a box, x fastest.
std::vector<float> Region(vtkDataArray* scalars, const int dims[3], const int lo[3], const int rd[3])
{
  std::vector<float> roi(static_cast<size_t>(rd[0]) * rd[1] * rd[2]);
  vtkSMPTools::For(0, rd[2], [&](vtkIdType k0, vtkIdType k1) {
    for (int k = static_cast<int>(k0); k < k1; ++k)
      for (int j = 0; j < rd[1]; ++j)
      {
        const vtkIdType row = (static_cast<vtkIdType>(k + lo[2]) * dims[1] + (j + lo[1])) * dims[0] + lo[0];
        float* out = roi.data() + (static_cast<size_t>(k) * rd[1] + j) * rd[0];
        for (int i = 0; i < rd[0]; ++i)
          out[i] = static_cast<float>(scalars->GetComponent(row + i, 0));
      }
  });
  return roi;
}

// The part of a box's values (box at lo, size rd) in a box inside it (at sub, size sd).
std::vector<float> SubRegion(
  const std::vector<float>& values, const int lo[3], const int rd[3], const int sub[3], const int sd[3])
{
  std::vector<float> out(static_cast<size_t>(sd[0]) * sd[1] * sd[2]);
  for (int k = 0; k < sd[2]; ++k)
    for (int j = 0; j < sd[1]; ++j)
    {
      const float* from = values.data() +
        (static_cast<size_t>(k + sub[2] - lo[2]) * rd[1] + (j + sub[1] - lo[1])) * rd[0] + (sub[0] - lo[0]);
      std::copy(from, from + sd[0], out.data() + (static_cast<size_t>(k) * sd[1] + j) * sd[0]);
    }
  return out;
}

// One organ's contour: its region of interest, its tracker, and how it ended.
struct Organ
{
  int Lo[3], Size[3];
  std::unique_ptr<amSnakeTracker> Tracker;
  bool Segmented = false;
  long AirSeed = -1; // a seed found in air, before any contour
};

// The organs' regions overlap (each reaches MaximumDistance from its seeds): the box that holds
// them all (lo, size) is smoothed once, on every core, and each organ takes its part.
std::vector<float> SmoothedBoxOfAll(const std::vector<Organ>& organs, vtkDataArray* scalars, const int dims[3],
  const double spacing[3], double sigma, int lo[3], int size[3])
{
  for (int a = 0; a < 3; ++a)
  {
    int hi = 0;
    lo[a] = dims[a];
    for (const Organ& organ : organs)
    {
      lo[a] = std::min(lo[a], organ.Lo[a]);
      hi = std::max(hi, organ.Lo[a] + organ.Size[a]);
    }
    size[a] = hi - lo[a];
  }
  return amSnakeTracker::Smooth(size, spacing, sigma, Region(scalars, dims, lo, size));
}

// The organ's region as the seeds' competition takes it: its box, its voxels, its interval and its
// seeds (voxel indices).
amSeedCompetition::Organ CompetingRegion(int label, const Organ& organ, const std::vector<std::array<double, 3>>& seeds)
{
  amSeedCompetition::Organ region;
  region.Label = label;
  std::copy(organ.Lo, organ.Lo + 3, region.Lo);
  std::copy(organ.Size, organ.Size + 3, region.Size);
  region.Inside = &organ.Tracker->Inside();
  region.Lower = organ.Tracker->Lower();
  region.Upper = organ.Tracker->Upper();
  for (const std::array<double, 3>& s : seeds)
    region.Seeds.push_back({ static_cast<int>(std::lround(s[0])), static_cast<int>(std::lround(s[1])),
      static_cast<int>(std::lround(s[2])) });
  return region;
}

// The organs, largest region first, so that the last one to start is a small one.
std::vector<size_t> LargestFirst(const std::vector<Organ>& organs)
{
  std::vector<size_t> schedule(organs.size());
  std::iota(schedule.begin(), schedule.end(), 0);
  auto voxels = [&](size_t li) {
    return static_cast<double>(organs[li].Size[0]) * organs[li].Size[1] * organs[li].Size[2];
  };
  std::stable_sort(schedule.begin(), schedule.end(), [&](size_t a, size_t b) { return voxels(a) > voxels(b); });
  return schedule;
}

// The seeds' labels in the order they first appear: their precedence.
std::vector<int> LabelsInOrder(const std::vector<Seed>& seeds)
{
  std::vector<int> order;
  for (const Seed& s : seeds)
    if (std::find(order.begin(), order.end(), s.Label) == order.end())
      order.push_back(s.Label);
  return order;
}

// The tracker's parameters: the filter's properties of the same names; on an image that carries
// the window it was stored through (amIntensityWindow), its intensities in HU become the image's.
amSnakeTracker::Parameters TrackerParameters(amSnakeSegmentation* f, vtkImageData* image)
{
  amSnakeTracker::Parameters tp;
  tp.Mode = f->GetMode();
  tp.SliceAxis = f->GetSliceAxis();
  tp.ContourModel = f->GetContourModel();
  tp.SmoothingSigma = f->GetSmoothingSigma();
  tp.SeedRadius = f->GetSeedRadius();
  tp.AutomaticThresholds = f->GetAutomaticThresholds();
  tp.IntensityTolerance = f->GetIntensityTolerance();
  tp.MinimumIntensityWindow = f->GetMinimumIntensityWindow();
  tp.LowerThreshold = f->GetLowerThreshold();
  tp.UpperThreshold = f->GetUpperThreshold();
  tp.PropagationScaling = f->GetPropagationScaling();
  tp.CurvatureScaling = f->GetCurvatureScaling();
  tp.EdgeWeight = f->GetEdgeWeight();
  tp.MaximumRMSError = f->GetMaximumRMSError();
  tp.NumberOfIterations = f->GetNumberOfIterations();
  tp.MaximumAreaChange = f->GetMaximumAreaChange();
  tp.MinimumSliceArea = f->GetMinimumSliceArea();
  tp.RefineToHalfContrast = f->GetRefineToHalfContrast();
  tp.CoarseToFine = f->GetCoarseToFine();
  tp.AdaptiveSliceStatistics = f->GetAdaptiveSliceStatistics();
  tp.OutsideThreshold = f->GetOutsideThreshold();
  tp.EdgeContrast = f->GetEdgeContrast();
  tp.MaximumRadius = f->GetMaximumRadius();
  tp.MaximumGrowth = f->GetMaximumGrowth();
  tp.AreaCost = f->GetAreaCost();
  tp.MinimumSectionContrast = f->GetMinimumSectionContrast();
  double window[2];
  if (amIntensityWindow::Of(image, window))
  {
    tp.MinimumIntensityWindow = amIntensityWindow::Width(window, tp.MinimumIntensityWindow);
    tp.EdgeContrast = amIntensityWindow::Width(window, tp.EdgeContrast);
    tp.LowerThreshold = amIntensityWindow::Level(window, tp.LowerThreshold);
    tp.UpperThreshold = amIntensityWindow::Level(window, tp.UpperThreshold);
    tp.OutsideThreshold = amIntensityWindow::Level(window, tp.OutsideThreshold);
  }
  return tp;
}
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
  , SeedsCompete(true)
  , RefineToHalfContrast(true)
  , CoarseToFine(true)
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

std::string amSnakeSegmentation::ProvenanceParameters(std::size_t seedCount) const
{
  std::ostringstream params;
  params << "Mode=" << (this->Mode == ThreeD ? "ThreeD" : "SliceBySlice") << " Seeds=" << seedCount
         << " SmoothingSigma=" << this->SmoothingSigma << " SeedRadius=" << this->SeedRadius
         << " AutomaticThresholds=" << this->AutomaticThresholds << " IntensityTolerance=" << this->IntensityTolerance
         << " MinimumIntensityWindow=" << this->MinimumIntensityWindow << " Propagation=" << this->PropagationScaling
         << " Curvature=" << this->CurvatureScaling << " EdgeWeight=" << this->EdgeWeight
         << " Iterations=" << this->NumberOfIterations << " MaximumDistance=" << this->MaximumDistance
         << " ContourModel=" << (this->ContourModel == Polar ? "Polar" : "LevelSet");
  if (this->Mode == ThreeD)
    params << " CoarseToFine=" << this->CoarseToFine;
  if (!this->SeedsCompete)
    params << " SeedsCompete=0";
  if (this->ContourModel == Polar)
    params << " OutsideThreshold=" << this->OutsideThreshold << " EdgeContrast=" << this->EdgeContrast
           << " MaximumRadius=" << this->MaximumRadius << " MaximumGrowth=" << this->MaximumGrowth
           << " AreaCost=" << this->AreaCost << " MinimumSectionContrast=" << this->MinimumSectionContrast;
  return params.str();
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

  std::vector<Seed> seeds;
  if (!GatherSeeds(input, this->Seeds, seedSet, this->SeedLabelArrayName, this->SeedLabel, seeds, why))
  {
    vtkErrorMacro(<< why);
    return 0;
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
  const std::vector<int> order = LabelsInOrder(seeds); // the precedence

  if (const long long bad = amInputCheck::NonFinite(scalars))
  {
    vtkErrorMacro("The input image has " << bad << " non-finite values (NaN or infinite); cannot segment them.");
    return 0;
  }
  double range[2];
  scalars->GetRange(range, 0);

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
  const double voxelVolume = spacing[0] * spacing[1] * spacing[2];
  const amSnakeTracker::Parameters tp = TrackerParameters(this, input);

  // Each organ's contour is independent of the others (its own region of interest, its own
  // intensity interval), so the organs run at once, one per core; the pasting below keeps the
  // precedence of their order.
  std::vector<Organ> organs(order.size());
  std::vector<std::vector<std::array<double, 3>>> organSeeds(order.size());
  for (size_t li = 0; li < order.size(); ++li)
  {
    for (const Seed& s : seeds)
      if (s.Label == order[li])
        organSeeds[li].push_back({ s.Index[0], s.Index[1], s.Index[2] });
    // 1. Region of interest around the seeds.
    RegionAround(organSeeds[li], this->MaximumDistance, spacing, dims, organs[li].Lo, organs[li].Size);
  }
  int ulo[3], urd[3];
  const std::vector<float> smoothed = SmoothedBoxOfAll(organs, scalars, dims, spacing, tp.SmoothingSigma, ulo, urd);
  const std::vector<size_t> schedule = LargestFirst(organs);
  amConcurrentTasks::Run(
    order.size(), 0,
    [&](size_t task, std::atomic<double>& fraction, const std::atomic<bool>& abort) {
      const size_t li = schedule[task];
      Organ& organ = organs[li];
      const std::vector<std::array<double, 3>>& mine = organSeeds[li];
      const int* lo = organ.Lo;
      const int* rd = organ.Size;
      organ.Tracker.reset(new amSnakeTracker(tp, spacing));
      amSnakeTracker& tracker = *organ.Tracker;
      tracker.SetSmoothedRegion(lo, rd, SubRegion(smoothed, ulo, urd, lo, rd));
      fraction = 0.1;
      // 2. Intensity statistics in the seed balls; a seed in air (a CT in HU) is a mistake.
      tracker.MeasureSeeds(mine);
      for (size_t s = 0; s < mine.size() && organ.AirSeed < 0; ++s)
        if (!this->AllowAirSeeds && range[0] <= -900.0 && tracker.SeedMean(s) < -950.0)
          organ.AirSeed = static_cast<long>(s);
      // 3. The contour.
      if (organ.AirSeed < 0)
        organ.Segmented = tracker.Segment(
          range[1], [&](double f) { fraction = f; }, [&]() { return abort.load(); });
    },
    [this](double f) { this->UpdateProgress(f); }, [this]() { return this->GetAbortExecute() != 0; });

  std::vector<amSeedCompetition::Organ> regions(order.size());
  for (size_t li = 0; li < order.size(); ++li)
  {
    const int label = order[li];
    Organ& organ = organs[li];
    amSnakeTracker& tracker = *organ.Tracker;
    if (organ.AirSeed >= 0)
    {
      const std::array<double, 3>& seed = organSeeds[li][static_cast<size_t>(organ.AirSeed)];
      double w[3];
      input->TransformContinuousIndexToPhysicalPoint(seed[0] + extent[0], seed[1] + extent[2], seed[2] + extent[4], w);
      vtkErrorMacro("Seed (" << w[0] << ", " << w[1] << ", " << w[2] << ") for label " << label << " lies in air (mean "
                             << tracker.SeedMean(static_cast<size_t>(organ.AirSeed))
                             << " HU around it); move it into the organ, or set AllowAirSeeds.");
      return 0;
    }
    if (!organ.Segmented)
    {
      if (!tracker.Error.empty())
        vtkErrorMacro("Level-set evolution failed for label " << label << ": " << tracker.Error);
      return 0;
    }
    thresholds->InsertNextTuple3(label, tracker.Lower(), tracker.Upper());
    regions[li] = CompetingRegion(label, organ, organSeeds[li]);
  }
  // The label map: shared voxels to the seeds nearest along paths that a wall between the organs
  // lengthens (or by precedence). A polar contour has no interval of its own: path length alone.
  const std::vector<std::size_t> voxels = amSeedCompetition::Paste(
    regions, dims, spacing, this->SeedsCompete, out, this->ContourModel == LevelSet ? smoothed.data() : nullptr);
  for (size_t li = 0; li < order.size(); ++li)
  {
    volumes->InsertNextTuple2(order[li], voxels[li] * voxelVolume);
    if (voxels[li] == 0)
      vtkWarningMacro("Label " << order[li] << ": the contour vanished (no voxel in [" << organs[li].Tracker->Lower()
                               << ", " << organs[li].Tracker->Upper()
                               << "] around its seeds, or every voxel taken by another label).");
  }
  organs.clear();
  this->UpdateProgress(1.0);

  output->CopyStructure(input);
  output->GetPointData()->SetScalars(labelArray);
  output->GetFieldData()->AddArray(thresholds);
  output->GetFieldData()->AddArray(volumes);
  amProvenance::Record(output, input, "amSnakeSegmentation", this->ProvenanceParameters(seeds.size()));
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
  os << indent << "CoarseToFine: " << this->CoarseToFine << "\n";
  os << indent << "ContourModel: " << (this->ContourModel == Polar ? "Polar" : "LevelSet") << "\n";
  os << indent << "OutsideThreshold: " << this->OutsideThreshold << "\n";
  os << indent << "EdgeContrast: " << this->EdgeContrast << "\n";
  os << indent << "MaximumRadius: " << this->MaximumRadius << " mm\n";
  os << indent << "MaximumGrowth: " << this->MaximumGrowth << " mm\n";
  os << indent << "AreaCost: " << this->AreaCost << " per mm\n";
  os << indent << "MinimumSectionContrast: " << this->MinimumSectionContrast << "\n";
}
