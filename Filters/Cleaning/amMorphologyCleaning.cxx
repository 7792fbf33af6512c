#include "amMorphologyCleaning.h"

#include "amLabelCleaning.h"
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

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(amMorphologyCleaning);

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

  const amLabelCleaning::Grid grid{ { dims[0], dims[1], dims[2] }, { spacing[0], spacing[1], spacing[2] } };
  amLabelCleaning::Settings settings;
  settings.Operation = this->Operation;
  settings.Radius = this->Radius;
  settings.MinimumComponentVolume = this->MinimumComponentVolume;
  settings.KeepLargestComponent = this->KeepLargestComponent;
  settings.FillHoles = this->FillHoles;
  std::vector<amLabelCleaning::Removed> dropped;
  for (size_t li = 0; li < labels.size(); ++li)
  {
    this->UpdateProgress(0.8 * li / labels.size());
    if (!amLabelCleaning::CleanLabel(grid, settings, labels[li], out, dropped, why))
    {
      vtkErrorMacro(<< why);
      return 0;
    }
    if (this->GetAbortExecute())
      return 0;
  }
  for (const auto& d : dropped)
    removed->InsertNextTuple3(d.Label, d.Voxels, d.Volume);

  if (this->SmoothingSigma > 0)
    amLabelCleaning::Smooth(grid, this->SmoothingSigma, out, [this](double f) { this->UpdateProgress(0.8 + 0.2 * f); });

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
