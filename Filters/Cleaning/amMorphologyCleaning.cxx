#include "amMorphologyCleaning.h"

#include "amLabelModeFilter.h"

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
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryDilateImageFilter.h>
#include <itkBinaryErodeImageFilter.h>
#include <itkBinaryFillholeImageFilter.h>
#include <itkBinaryMorphologicalClosingImageFilter.h>
#include <itkBinaryMorphologicalOpeningImageFilter.h>
#include <itkConnectedComponentImageFilter.h>
#include <itkRelabelComponentImageFilter.h>
#include <itkSmoothingRecursiveGaussianImageFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(amMorphologyCleaning);

namespace
{
using Mask = itk::Image<unsigned char, 3>;
using Ball = itk::BinaryBallStructuringElement<unsigned char, 3>;

struct Box
{
  int Lo[3], Hi[3];
  int Size(int a) const { return this->Hi[a] - this->Lo[a] + 1; }
};

template<typename FilterType>
Mask::Pointer Morph(Mask* in, const Ball& ball)
{
  auto f = FilterType::New();
  f->SetInput(in);
  f->SetKernel(ball);
  f->SetForegroundValue(1);
  f->Update();
  return f->GetOutput();
}
}

amMorphologyCleaning::amMorphologyCleaning()
  : Operation(None)
  , Radius(1.0)
  , MinimumComponentVolume(0.0)
  , KeepLargestComponent(false)
  , FillHoles(false)
  , SmoothingSigma(0.0)
  , ModeFilterRadius(0)
  , ModeFilterPasses(1)
{
  amThreading::Initialize();
}

amMorphologyCleaning::~amMorphologyCleaning() = default;

void amMorphologyCleaning::AddLabel(int label)
{
  this->Labels.push_back(label);
  this->Modified();
}

void amMorphologyCleaning::RemoveAllLabels()
{
  if (!this->Labels.empty())
  {
    this->Labels.clear();
    this->Modified();
  }
}

int amMorphologyCleaning::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  const vtkIdType n = scalars->GetNumberOfTuples();
  std::vector<unsigned char> out;
  if (!amInputCheck::LabelBytes(scalars, 255, out, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  int dims[3];
  input->GetDimensions(dims);
  vtkNew<vtkIdTypeArray> modeChanged;
  modeChanged->SetName("ModeFilterChanged");
  if (this->ModeFilterRadius > 0)
  {
    vtkIdType total = 0;
    for (int pass = 0; pass < this->ModeFilterPasses; ++pass)
    {
      const std::size_t changed = amLabelMode::Pass(dims, this->ModeFilterRadius, out);
      total += static_cast<vtkIdType>(changed);
      if (changed == 0)
        break;
    }
    modeChanged->InsertNextValue(total);
  }
  const double* spacing = input->GetSpacing();
  const double voxelVolume = spacing[0] * spacing[1] * spacing[2];
  const vtkIdType sx = 1, sy = dims[0], sz = static_cast<vtkIdType>(dims[0]) * dims[1];

  std::array<vtkIdType, 256> before{};
  for (unsigned char v : out)
    ++before[v];
  std::vector<int> labels = this->Labels;
  if (labels.empty())
    for (int l = 1; l < 256; ++l)
      if (before[l])
        labels.push_back(l);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());

  vtkNew<vtkDoubleArray> removed;
  removed->SetName("RemovedComponents");
  removed->SetNumberOfComponents(3);
  removed->SetComponentName(0, "Label");
  removed->SetComponentName(1, "Voxels");
  removed->SetComponentName(2, "Volume_mm3");

  const bool morph = this->Operation != None && this->Radius > 0;
  int r[3];
  for (int a = 0; a < 3; ++a)
    r[a] = morph ? static_cast<int>(std::lround(this->Radius / spacing[a])) : 0;
  const int pad = std::max(r[0], std::max(r[1], r[2])) + 2;

  // Hand voxels given up by 'from' to their neighbours (most frequent 26-neighbour label other
  // than 'from' among voxels that keep theirs), pass after pass; what no neighbour takes becomes 0.
  auto handOver = [&](std::vector<vtkIdType>& released, int from) {
    if (released.empty())
      return;
    std::vector<char> pending(static_cast<size_t>(n), 0);
    for (vtkIdType id : released)
      pending[id] = 1;
    while (!released.empty())
    {
      std::vector<std::pair<vtkIdType, unsigned char>> assign;
      std::vector<vtkIdType> still;
      for (vtkIdType id : released)
      {
        const int i = static_cast<int>(id % dims[0]), j = static_cast<int>((id / dims[0]) % dims[1]),
                  k = static_cast<int>(id / sz);
        std::array<int, 256> votes{};
        int best = -1, bestVotes = 0;
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
            {
              const int ii = i + di, jj = j + dj, kk = k + dk;
              if ((!di && !dj && !dk) || ii < 0 || jj < 0 || kk < 0 || ii >= dims[0] || jj >= dims[1] || kk >= dims[2])
                continue;
              const vtkIdType nid = kk * sz + jj * sy + ii * sx;
              if (pending[nid] || out[nid] == from)
                continue;
              const int c = ++votes[out[nid]];
              if (c > bestVotes || (c == bestVotes && out[nid] < best))
              {
                best = out[nid];
                bestVotes = c;
              }
            }
        if (best >= 0)
          assign.emplace_back(id, static_cast<unsigned char>(best));
        else
          still.push_back(id);
      }
      if (assign.empty())
      {
        for (vtkIdType id : still)
          out[id] = 0;
        break;
      }
      for (const auto& a : assign)
      {
        out[a.first] = a.second;
        pending[a.first] = 0;
      }
      released.swap(still);
    }
  };

  for (size_t li = 0; li < labels.size(); ++li)
  {
    const int label = labels[li];
    this->UpdateProgress(0.8 * li / labels.size());
    Box box{ { dims[0], dims[1], dims[2] }, { -1, -1, -1 } };
    for (vtkIdType id = 0; id < n; ++id)
      if (out[id] == label)
      {
        const int ijk[3] = { static_cast<int>(id % dims[0]), static_cast<int>((id / dims[0]) % dims[1]),
          static_cast<int>(id / sz) };
        for (int a = 0; a < 3; ++a)
        {
          box.Lo[a] = std::min(box.Lo[a], ijk[a]);
          box.Hi[a] = std::max(box.Hi[a], ijk[a]);
        }
      }
    if (box.Hi[0] < 0)
      continue; // not present
    for (int a = 0; a < 3; ++a)
    {
      box.Lo[a] = std::max(0, box.Lo[a] - pad);
      box.Hi[a] = std::min(dims[a] - 1, box.Hi[a] + pad);
    }
    auto mask = Mask::New();
    Mask::RegionType region;
    Mask::SizeType size = { { static_cast<itk::SizeValueType>(box.Size(0)),
      static_cast<itk::SizeValueType>(box.Size(1)), static_cast<itk::SizeValueType>(box.Size(2)) } };
    region.SetSize(size);
    mask->SetRegions(region);
    Mask::SpacingType sp;
    for (int a = 0; a < 3; ++a)
      sp[a] = spacing[a];
    mask->SetSpacing(sp);
    mask->Allocate();
    auto roiId = [&](int i, int j, int k) { return (static_cast<size_t>(k) * box.Size(1) + j) * box.Size(0) + i; };
    auto globalId = [&](int i, int j, int k) {
      return (static_cast<vtkIdType>(k + box.Lo[2]) * dims[1] + (j + box.Lo[1])) * dims[0] + (i + box.Lo[0]);
    };
    for (int k = 0; k < box.Size(2); ++k)
      for (int j = 0; j < box.Size(1); ++j)
        for (int i = 0; i < box.Size(0); ++i)
          mask->GetBufferPointer()[roiId(i, j, k)] = out[globalId(i, j, k)] == label ? 1 : 0;

    Mask::Pointer result = mask;
    try
    {
      if (morph)
      {
        Ball ball;
        Ball::SizeType radius;
        for (int a = 0; a < 3; ++a)
          radius[a] = static_cast<itk::SizeValueType>(r[a]);
        ball.SetRadius(radius);
        ball.CreateStructuringElement();
        switch (this->Operation)
        {
          case Erode:
            result = Morph<itk::BinaryErodeImageFilter<Mask, Mask, Ball>>(result, ball);
            break;
          case Dilate:
            result = Morph<itk::BinaryDilateImageFilter<Mask, Mask, Ball>>(result, ball);
            break;
          case Open:
            result = Morph<itk::BinaryMorphologicalOpeningImageFilter<Mask, Mask, Ball>>(result, ball);
            break;
          case Close:
            result = Morph<itk::BinaryMorphologicalClosingImageFilter<Mask, Mask, Ball>>(result, ball);
            break;
          default:
            break;
        }
      }
      if (this->MinimumComponentVolume > 0 || this->KeepLargestComponent)
      {
        using LabelImage = itk::Image<unsigned int, 3>;
        auto cc = itk::ConnectedComponentImageFilter<Mask, LabelImage>::New();
        cc->SetInput(result);
        cc->SetFullyConnected(false);
        auto relabel = itk::RelabelComponentImageFilter<LabelImage, LabelImage>::New();
        relabel->SetInput(cc->GetOutput());
        relabel->Update();
        const auto& sizes = relabel->GetSizeOfObjectsInPixels();
        std::vector<char> drop(sizes.size() + 1, 0);
        for (size_t c = 0; c < sizes.size(); ++c)
          if ((this->KeepLargestComponent && c > 0) || sizes[c] * voxelVolume < this->MinimumComponentVolume)
          {
            drop[c + 1] = 1;
            removed->InsertNextTuple3(label, static_cast<double>(sizes[c]), sizes[c] * voxelVolume);
          }
        auto filtered = Mask::New();
        filtered->SetRegions(region);
        filtered->SetSpacing(sp);
        filtered->Allocate();
        const unsigned* c = relabel->GetOutput()->GetBufferPointer();
        for (size_t i = 0; i < region.GetNumberOfPixels(); ++i)
          filtered->GetBufferPointer()[i] = (c[i] && !drop[c[i]]) ? 1 : 0;
        result = filtered;
      }
      if (this->FillHoles)
      {
        auto fill = itk::BinaryFillholeImageFilter<Mask>::New();
        fill->SetInput(result);
        fill->SetForegroundValue(1);
        fill->SetFullyConnected(false);
        fill->Update();
        result = fill->GetOutput();
      }
    }
    catch (const itk::ExceptionObject& e)
    {
      vtkErrorMacro("Cleaning label " << label << " failed: " << e.GetDescription());
      return 0;
    }
    // Apply: grow only into unlabelled voxels; hand what is given up to the neighbours.
    std::vector<vtkIdType> released;
    const unsigned char* m = result->GetBufferPointer();
    for (int k = 0; k < box.Size(2); ++k)
      for (int j = 0; j < box.Size(1); ++j)
        for (int i = 0; i < box.Size(0); ++i)
        {
          const vtkIdType g = globalId(i, j, k);
          const bool keep = m[roiId(i, j, k)] != 0;
          if (out[g] == label && !keep)
            released.push_back(g);
          else if (out[g] == 0 && keep)
            out[g] = static_cast<unsigned char>(label);
        }
    handOver(released, label);
    if (this->GetAbortExecute())
      return 0;
  }

  // Label-preserving Gaussian regularisation: argmax of the smoothed indicators.
  if (this->SmoothingSigma > 0)
  {
    std::array<vtkIdType, 256> present{};
    for (unsigned char v : out)
      ++present[v];
    using FloatImage = itk::Image<float, 3>;
    FloatImage::RegionType region;
    FloatImage::SizeType size = { { static_cast<itk::SizeValueType>(dims[0]), static_cast<itk::SizeValueType>(dims[1]),
      static_cast<itk::SizeValueType>(dims[2]) } };
    region.SetSize(size);
    FloatImage::SpacingType sp;
    for (int a = 0; a < 3; ++a)
      sp[a] = spacing[a];
    std::vector<float> best(static_cast<size_t>(n), -1.0f);
    std::vector<unsigned char> bestLabel(out);
    auto indicator = FloatImage::New();
    indicator->SetRegions(region);
    indicator->SetSpacing(sp);
    indicator->Allocate();
    int done = 0;
    const int total =
      static_cast<int>(std::count_if(present.begin(), present.end(), [](vtkIdType c) { return c > 0; }));
    for (int l = 0; l < 256; ++l)
    {
      if (!present[l])
        continue;
      float* ind = indicator->GetBufferPointer();
      for (vtkIdType i = 0; i < n; ++i)
        ind[i] = out[i] == l ? 1.0f : 0.0f;
      auto smooth = itk::SmoothingRecursiveGaussianImageFilter<FloatImage, FloatImage>::New();
      smooth->SetInput(indicator);
      smooth->SetSigma(this->SmoothingSigma);
      smooth->Update();
      const float* s = smooth->GetOutput()->GetBufferPointer();
      vtkSMPTools::For(0, n, [&](vtkIdType b, vtkIdType e) {
        for (vtkIdType i = b; i < e; ++i)
          if (s[i] > best[i] + 1e-6f || (s[i] >= best[i] - 1e-6f && out[i] == l))
          {
            best[i] = s[i];
            bestLabel[i] = static_cast<unsigned char>(l);
          }
      });
      this->UpdateProgress(0.8 + 0.2 * (++done) / total);
    }
    out.swap(bestLabel);
  }

  std::array<vtkIdType, 256> after{};
  for (unsigned char v : out)
    ++after[v];
  vtkNew<vtkDoubleArray> volumes;
  volumes->SetName("LabelVolumes");
  volumes->SetNumberOfComponents(3);
  volumes->SetComponentName(0, "Label");
  volumes->SetComponentName(1, "Before_mm3");
  volumes->SetComponentName(2, "After_mm3");
  vtkNew<vtkIntArray> vanished;
  vanished->SetName("VanishedLabels");
  for (int l = 0; l < 256; ++l)
  {
    if (before[l] || after[l])
      volumes->InsertNextTuple3(l, before[l] * voxelVolume, after[l] * voxelVolume);
    if (l > 0 && before[l] && !after[l])
    {
      vanished->InsertNextValue(l);
      vtkWarningMacro("Label " << l << " (" << before[l] * voxelVolume
                               << " mm3 in the input) vanished: the cleaning removed all of it.");
    }
  }
  vtkNew<vtkUnsignedCharArray> labelArray;
  labelArray->SetName("Labels");
  labelArray->SetNumberOfTuples(n);
  std::copy(out.begin(), out.end(), labelArray->GetPointer(0));
  output->CopyStructure(input);
  output->GetPointData()->SetScalars(labelArray);
  output->GetFieldData()->PassData(input->GetFieldData());
  if (modeChanged->GetNumberOfTuples() > 0)
    output->GetFieldData()->AddArray(modeChanged);
  output->GetFieldData()->AddArray(removed);
  output->GetFieldData()->AddArray(volumes);
  output->GetFieldData()->AddArray(vanished);
  std::ostringstream params;
  static const char* ops[] = { "None", "Erode", "Dilate", "Open", "Close" };
  params << "Operation=" << ops[this->Operation] << " Radius=" << this->Radius
         << " MinimumComponentVolume=" << this->MinimumComponentVolume
         << " KeepLargestComponent=" << this->KeepLargestComponent << " FillHoles=" << this->FillHoles
         << " SmoothingSigma=" << this->SmoothingSigma << " ModeFilterRadius=" << this->ModeFilterRadius
         << " ModeFilterPasses=" << this->ModeFilterPasses;
  amProvenance::Record(output, input, "amMorphologyCleaning", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amMorphologyCleaning::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Operation: " << this->Operation << " Radius: " << this->Radius << " mm\n";
  os << indent << "MinimumComponentVolume: " << this->MinimumComponentVolume << " mm3\n";
  os << indent << "KeepLargestComponent: " << this->KeepLargestComponent << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "SmoothingSigma: " << this->SmoothingSigma << " mm\n";
  os << indent << "ModeFilterRadius: " << this->ModeFilterRadius << " voxels, passes " << this->ModeFilterPasses
     << "\n";
}
