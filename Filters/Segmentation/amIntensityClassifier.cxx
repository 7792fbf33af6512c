#include "amIntensityClassifier.h"

#include "Anatomy/amTissueClassTable.h"
#include "amITKBridge.h"
#include "amInputCheck.h"
#include "amProvenance.h"
#include "amThreading.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <itkOtsuMultipleThresholdsCalculator.h>
#include <itkScalarImageToHistogramGenerator.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(amIntensityClassifier);

namespace
{
// The CT defaults: boundaries half-way between typical tissue values (HU).
const double DefaultRanges[] = { -925, -475, 1, -475, -30, 2, -30, 170, 3, 170, 400, 4, 400, 1e30, 5 };
const char* DefaultNames[] = { "Unclassified", "Lung", "Fat", "SoftTissue", "ContrastBlood", "Bone" };

// Calls f(neighbour) for the 6 face neighbours of voxel id inside the grid.
template<typename F>
void FaceNeighbours(const int dims[3], vtkIdType id, F&& f)
{
  const vtkIdType sy = dims[0], sz = static_cast<vtkIdType>(dims[0]) * dims[1];
  const vtkIdType row = id / dims[0];
  const int i = static_cast<int>(id - row * dims[0]), j = static_cast<int>(row % dims[1]),
            k = static_cast<int>(row / dims[1]);
  if (i > 0)
    f(id - 1);
  if (i < dims[0] - 1)
    f(id + 1);
  if (j > 0)
    f(id - sy);
  if (j < dims[1] - 1)
    f(id + sy);
  if (k > 0)
    f(id - sz);
  if (k < dims[2] - 1)
    f(id + sz);
}

// The voxels that open() lets through and that connect (across faces) to the sides of the first
// two index axes. A scan-line flood: runs along the first axis, each seeding the rows beside it.
template<typename Open>
std::vector<unsigned char> FloodFromSides(const int dims[3], Open&& open)
{
  const vtkIdType sy = dims[0], sz = static_cast<vtkIdType>(dims[0]) * dims[1];
  std::vector<unsigned char> reached(static_cast<size_t>(sz * dims[2]), 0);
  std::vector<vtkIdType> front; // a voxel from which to fill a run
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        if (i == 0 || j == 0 || i == dims[0] - 1 || j == dims[1] - 1)
        {
          const vtkIdType id = k * sz + j * sy + i;
          if (open(id))
            front.push_back(id);
        }
  while (!front.empty())
  {
    const vtkIdType id = front.back();
    front.pop_back();
    if (reached[id])
      continue;
    const vtkIdType rowStart = id - id % sy;
    vtkIdType lo = id, hi = id;
    while (lo > rowStart && !reached[lo - 1] && open(lo - 1))
      --lo;
    while (hi + 1 < rowStart + sy && !reached[hi + 1] && open(hi + 1))
      ++hi;
    std::fill(reached.begin() + lo, reached.begin() + hi + 1, 1);
    const vtkIdType row = id / sy;
    const int j = static_cast<int>(row % dims[1]), k = static_cast<int>(row / dims[1]);
    // The rows beside the run: one voxel of each open stretch seeds it.
    const auto seedRow = [&](vtkIdType offset) {
      bool inside = false;
      for (vtkIdType q = lo + offset; q <= hi + offset; ++q)
      {
        const bool free = !reached[q] && open(q);
        if (free && !inside)
          front.push_back(q);
        inside = free;
      }
    };
    if (j > 0)
      seedRow(-sy);
    if (j < dims[1] - 1)
      seedRow(sy);
    if (k > 0)
      seedRow(-sz);
    if (k < dims[2] - 1)
      seedRow(sz);
  }
  return reached;
}

// The body, for the histogram of the automatic classes: all but the air open to the sides (below
// -950 HU, so a lung that a field of view cuts, -850 HU at the side, stays in the body) and the
// skin's partial volume beside it (below -500 HU, half-way to water, within three voxels).
std::vector<unsigned char> Body(const int dims[3], const std::vector<double>& values)
{
  std::vector<unsigned char> outside = FloodFromSides(dims, [&](vtkIdType id) { return values[id] < -950.0; });
  for (int ring = 0; ring < 3; ++ring)
  {
    std::vector<unsigned char> grown = outside;
    vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()), [&](vtkIdType id0, vtkIdType id1) {
      for (vtkIdType id = id0; id < id1; ++id)
        if (!outside[id] && values[id] < -500.0)
          FaceNeighbours(dims, id, [&](vtkIdType q) { grown[id] = grown[id] || outside[q]; });
    });
    outside.swap(grown);
  }
  for (auto& v : outside)
    v = !v;
  return outside;
}
}

amIntensityClassifier::amIntensityClassifier()
  : Mode(Ranges)
  , NumberOfClasses(4)
  , NumberOfHistogramBins(128)
  , Window(1500.0)
  , Level(-300.0)
  , ClassifyWindowed(false)
  , ExteriorAir(true)
  , ExteriorThreshold(-480.0)
{
  amThreading::Initialize();
  this->SetNumberOfOutputPorts(2);
}

amIntensityClassifier::~amIntensityClassifier() = default;

void amIntensityClassifier::AddRange(double low, double high, double label)
{
  this->RangeList.push_back(low);
  this->RangeList.push_back(high);
  this->RangeList.push_back(label);
  this->Modified();
}

void amIntensityClassifier::RemoveAllRanges()
{
  if (!this->RangeList.empty())
  {
    this->RangeList.clear();
    this->Modified();
  }
}

int amIntensityClassifier::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  for (int port = 0; port < 2; ++port)
    vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(port), VTK_UNSIGNED_CHAR, 1);
  return 1;
}

namespace
{
// Otsu's thresholds of the values' histogram as ranges (low, high, label 1..classes), the
// thresholds themselves into thresholdsOut; false with 'why' when ITK fails.
bool OtsuRanges(const std::vector<double>& values, int bins, int classes, std::vector<double>& ranges,
  vtkDoubleArray* thresholdsOut, std::string& why)
{
  using ImageType = itk::Image<float, 3>;
  auto image = ImageType::New();
  ImageType::RegionType region;
  ImageType::SizeType size = { { static_cast<itk::SizeValueType>(values.size()), 1, 1 } };
  region.SetSize(size);
  image->SetRegions(region);
  image->Allocate();
  for (size_t i = 0; i < values.size(); ++i)
    image->GetBufferPointer()[i] = static_cast<float>(values[i]);
  using Generator = itk::Statistics::ScalarImageToHistogramGenerator<ImageType>;
  auto generator = Generator::New();
  generator->SetInput(image);
  generator->SetNumberOfBins(bins);
  generator->SetAutoHistogramMinimumMaximum(true);
  using Calculator = itk::OtsuMultipleThresholdsCalculator<Generator::HistogramType>;
  auto calculator = Calculator::New();
  try
  {
    generator->Compute();
    calculator->SetInputHistogram(generator->GetOutput());
    calculator->SetNumberOfThresholds(classes - 1);
    calculator->Compute();
  }
  catch (const itk::ExceptionObject& e)
  {
    why = std::string("Otsu thresholding failed: ") + e.GetDescription();
    return false;
  }
  const auto& thresholds = calculator->GetOutput();
  ranges.clear();
  double previous = -std::numeric_limits<double>::max();
  for (size_t k = 0; k <= thresholds.size(); ++k)
  {
    const double next = k < thresholds.size() ? thresholds[k] : std::numeric_limits<double>::max();
    if (k > 0)
    {
      ranges.push_back(previous);
      ranges.push_back(next);
      ranges.push_back(static_cast<double>(k));
    }
    previous = next;
  }
  for (double v : thresholds)
    thresholdsOut->InsertNextValue(v);
  return true;
}

// The scan windowed to 8 bits (w), and the values to classify: the windowed ones, or the scan's
// own. Returns the non-finite values found (both then 0 there).
vtkIdType WindowValues(
  vtkDataArray* scalars, double level, double window, bool useWindowed, unsigned char* w, std::vector<double>& values)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  const double lo = level - 0.5 * window, scale = 255.0 / window;
  std::atomic<vtkIdType> nans{ 0 };
  vtkSMPTools::For(0, n, [&](vtkIdType b, vtkIdType e) {
    vtkIdType bad = 0;
    for (vtkIdType i = b; i < e; ++i)
    {
      const double v = scalars->GetComponent(i, 0);
      if (!std::isfinite(v))
      {
        ++bad;
        w[i] = 0;
        values[i] = 0;
        continue;
      }
      const double c = std::floor((v - lo) * scale + 0.5);
      w[i] = static_cast<unsigned char>(c < 0 ? 0 : c > 255 ? 255 : c);
      values[i] = useWindowed ? w[i] : v;
    }
    nans += bad;
  });
  return nans;
}

// Each value's label: that of the first range [low, high) holding it, 0 for none.
void Classify(const std::vector<double>& values, const std::vector<double>& ranges, unsigned char* l)
{
  const size_t nr = ranges.size() / 3;
  vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      unsigned char label = 0;
      for (size_t r = 0; r < nr; ++r)
        if (values[i] >= ranges[3 * r] && values[i] < ranges[3 * r + 1])
        {
          label = static_cast<unsigned char>(ranges[3 * r + 2]);
          break;
        }
      l[i] = label;
    }
  });
}

// The air around the patient (the unlabelled voxels reached from the image's sides) and, two
// layers deep, the partial volume of the skin against it (darker than threshold, touching the
// outside air, with tissue within two voxels along an axis): labelled 0. Returns the partial-volume
// voxels taken.
vtkIdType ExteriorShell(const int dims[3], vtkDataArray* scalars, double threshold, unsigned char* l)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  vtkIdType count = 0;
  const vtkIdType sx = 1, sy = dims[0], sz = static_cast<vtkIdType>(dims[0]) * dims[1];
  std::vector<unsigned char> exterior = FloodFromSides(dims, [&](vtkIdType id) { return l[id] == 0; });
  for (int layer = 0; layer < 2; ++layer)
  {
    std::vector<vtkIdType> shell;
    for (vtkIdType id = 0; id < n; ++id)
      if (!exterior[id] && l[id] != 0 && scalars->GetComponent(id, 0) < threshold)
      {
        bool touches = false;
        FaceNeighbours(dims, id, [&](vtkIdType q) { touches = touches || exterior[q]; });
        // ... and tissue within two voxels along an axis: skin, not lung beside an air pocket.
        const int c[3] = { static_cast<int>(id % dims[0]), static_cast<int>((id / dims[0]) % dims[1]),
          static_cast<int>(id / sz) };
        const vtkIdType stride[3] = { sx, sy, sz };
        bool tissue = false;
        for (int a = 0; a < 3 && touches && !tissue; ++a)
          for (int d : { -2, -1, 1, 2 })
            if (c[a] + d >= 0 && c[a] + d < dims[a] && scalars->GetComponent(id + d * stride[a], 0) >= threshold)
              tissue = true;
        if (touches && tissue)
          shell.push_back(id);
      }
    for (vtkIdType id : shell)
    {
      exterior[id] = 1;
      l[id] = 0;
    }
    count += static_cast<vtkIdType>(shell.size());
  }
  return count;
}

}

int amIntensityClassifier::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkImageData* labelsOut = vtkImageData::GetData(outputVector, 0);
  vtkImageData* windowOut = vtkImageData::GetData(outputVector, 1);
  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  if (this->Mode == Ranges)
    for (size_t r = 0; r < this->RangeList.size(); r += 3)
      if (this->RangeList[r + 2] < 1 || this->RangeList[r + 2] > 255 || !(this->RangeList[r] < this->RangeList[r + 1]))
      {
        vtkErrorMacro("Range " << r / 3 << " [" << this->RangeList[r] << ", " << this->RangeList[r + 1] << ") -> "
                               << this->RangeList[r + 2] << " is invalid (low < high, label in 1..255).");
        return 0;
      }
  const vtkIdType n = scalars->GetNumberOfTuples();

  // The windowed 8-bit image, and the values to classify.
  std::vector<double> values(static_cast<size_t>(n));
  vtkNew<vtkUnsignedCharArray> windowed;
  windowed->SetName("Windowed");
  windowed->SetNumberOfTuples(n);
  unsigned char* w = windowed->GetPointer(0);
  const bool useWindowed = this->ClassifyWindowed;
  const vtkIdType nans = WindowValues(scalars, this->Level, this->Window, useWindowed, w, values);
  if (nans > 0)
  {
    vtkErrorMacro("The input has " << nans << " non-finite values (NaN or infinite); cannot classify them.");
    return 0;
  }
  this->UpdateProgress(0.3);

  std::vector<double> ranges = this->RangeList;
  amTissueMixture::Result mixture;
  std::vector<std::string> names;
  vtkNew<vtkDoubleArray> otsuThresholds;
  otsuThresholds->SetName("Thresholds");
  if (this->Mode == Otsu)
  {
    if (!OtsuRanges(values, this->NumberOfHistogramBins, this->NumberOfClasses, ranges, otsuThresholds, why))
    {
      vtkErrorMacro(<< why);
      return 0;
    }
  }
  else if (this->Mode == Automatic)
  {
    if (useWindowed)
    {
      vtkErrorMacro("Mode Automatic classifies values in HU: it cannot be combined with ClassifyWindowed.");
      return 0;
    }
    int dims[3];
    input->GetDimensions(dims);
    const std::vector<unsigned char> body = Body(dims, values);
    mixture = amTissueMixture::Fit(values.data(), body.data(), values.size());
    if (!mixture.Problem.empty())
    {
      vtkErrorMacro("The scan's tissue classes cannot be found: " << mixture.Problem << ".");
      return 0;
    }
    ranges.clear();
    for (int c = amTissueMixture::Lung; c < amTissueMixture::NumberOfClasses; ++c)
      if (mixture.Classes[c].Found || c == amTissueMixture::Bone) // bone's range is kept (amTissueMixture)
      {
        ranges.push_back(mixture.Upper[c - 1]);
        ranges.push_back(c == amTissueMixture::Bone ? 1e30 : mixture.Upper[c]);
        ranges.push_back(c);
      }
    names.assign(std::begin(DefaultNames), std::end(DefaultNames));
  }
  else if (ranges.empty())
  {
    ranges.assign(std::begin(DefaultRanges), std::end(DefaultRanges));
    names.assign(std::begin(DefaultNames), std::end(DefaultNames));
  }
  this->UpdateProgress(0.5);

  vtkNew<vtkUnsignedCharArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfTuples(n);
  unsigned char* l = labels->GetPointer(0);
  const size_t nr = ranges.size() / 3;
  Classify(values, ranges, l);

  // The air around the patient, and the partial volume of the skin against it.
  vtkIdType exteriorVoxels = 0;
  if (this->ExteriorAir)
  {
    int dims[3];
    input->GetDimensions(dims);
    exteriorVoxels = ExteriorShell(dims, scalars, this->ExteriorThreshold, l);
  }
  this->UpdateProgress(0.9);

  labelsOut->CopyStructure(input);
  windowOut->CopyStructure(input);
  labelsOut->GetPointData()->SetScalars(labels);
  windowOut->GetPointData()->SetScalars(windowed);
  if (this->Mode == Otsu) // after CopyStructure, which clears field data
    labelsOut->GetFieldData()->AddArray(otsuThresholds);
  if (!names.empty())
  {
    vtkNew<vtkStringArray> a;
    a->SetName("LabelNames");
    for (const auto& s : names)
      a->InsertNextValue(s);
    labelsOut->GetFieldData()->AddArray(a);
  }
  if (this->Mode == Automatic)
    labelsOut->GetFieldData()->AddArray(amTissueClassTable(mixture));
  if (this->ExteriorAir)
  {
    vtkNew<vtkIdTypeArray> a;
    a->SetName("ExteriorVoxels");
    a->InsertNextValue(exteriorVoxels);
    labelsOut->GetFieldData()->AddArray(a);
  }
  std::ostringstream params;
  params << "Mode=" << (this->Mode == Otsu ? "Otsu" : this->Mode == Automatic ? "Automatic" : "Ranges");
  if (this->Mode == Otsu)
    params << " NumberOfClasses=" << this->NumberOfClasses << " NumberOfHistogramBins=" << this->NumberOfHistogramBins;
  else
  {
    params << " Ranges=";
    for (size_t r = 0; r < nr; ++r)
      params << (r ? ";" : "") << "[" << ranges[3 * r] << "," << ranges[3 * r + 1] << ")->" << ranges[3 * r + 2];
  }
  params << " Window=" << this->Window << " Level=" << this->Level << " ClassifyWindowed=" << this->ClassifyWindowed
         << " ExteriorAir=" << this->ExteriorAir << " ExteriorThreshold=" << this->ExteriorThreshold;
  amProvenance::Record(labelsOut, input, "amIntensityClassifier", params.str());
  amProvenance::Record(windowOut, input, "amIntensityClassifier", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amIntensityClassifier::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "NumberOfRanges: " << this->RangeList.size() / 3 << "\n";
  os << indent << "NumberOfClasses: " << this->NumberOfClasses << "\n";
  os << indent << "Window: " << this->Window << " Level: " << this->Level << "\n";
  os << indent << "ClassifyWindowed: " << this->ClassifyWindowed << "\n";
  os << indent << "ExteriorAir: " << this->ExteriorAir << " (threshold " << this->ExteriorThreshold << ")\n";
}
