#include "amSyntheticAtlasSource.h"

#include "amProvenance.h"
#include "amSyntheticAtlas.h"
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
#include "vtkStreamingDemandDrivenPipeline.h"

#include <sstream>

vtkStandardNewMacro(amSyntheticAtlasSource);

amSyntheticAtlasSource::amSyntheticAtlasSource()
  : NumberOfLabels(50)
  , Dimensions{ 96, 96, 96 }
  , Spacing{ 1, 1, 1 }
  , SheetWidth(0)
  , NoiseFraction(0)
  , Seed(1)
  , OutputScalarType(VTK_SHORT)
{
  amThreading::Initialize();
  this->SetNumberOfInputPorts(0);
}

int amSyntheticAtlasSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  for (int d = 0; d < 3; ++d)
    if (this->Dimensions[d] < 1 || !(this->Spacing[d] > 0))
    {
      vtkErrorMacro("Dimensions must be >= 1 and spacings > 0 (axis " << d << ": " << this->Dimensions[d]
                                                                      << " voxels of " << this->Spacing[d] << " mm).");
      return 0;
    }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0, this->Dimensions[2] - 1 };
  const double origin[3] = { 0, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), this->Spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, this->OutputScalarType, 1);
  return 1;
}

int amSyntheticAtlasSource::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  const int type = this->OutputScalarType;
  double largest = 0;
  switch (type)
  {
    case VTK_UNSIGNED_CHAR:
      largest = 255;
      break;
    case VTK_SHORT:
      largest = 32767;
      break;
    case VTK_UNSIGNED_SHORT:
      largest = 65535;
      break;
    case VTK_INT:
      largest = 2147483647.0;
      break;
    default:
      vtkErrorMacro("OutputScalarType " << type << " is not an integer type this source writes (3 unsigned char, "
                                        << "4 short, 5 unsigned short, 6 int).");
      return 0;
  }
  const int labels = this->NumberOfLabels + (this->SheetWidth > 0 ? 1 : 0);
  if (labels > largest)
  {
    vtkErrorMacro(<< labels << " labels do not fit the output scalar type (largest " << largest << ").");
    return 0;
  }
  amSyntheticAtlas atlas;
  for (int d = 0; d < 3; ++d)
  {
    atlas.Dimensions[d] = this->Dimensions[d];
    atlas.Spacing[d] = this->Spacing[d];
  }
  atlas.NumberOfLabels = this->NumberOfLabels;
  atlas.SheetWidth = this->SheetWidth;
  atlas.NoiseFraction = this->NoiseFraction;
  atlas.Seed = static_cast<unsigned int>(this->Seed);
  this->UpdateProgress(0.05);
  const std::vector<int32_t> values = atlas.Generate();
  this->UpdateProgress(0.9);

  output->SetExtent(0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0, this->Dimensions[2] - 1);
  output->SetSpacing(this->Spacing);
  output->SetOrigin(0, 0, 0);
  output->AllocateScalars(type, 1);
  vtkDataArray* scalars = output->GetPointData()->GetScalars();
  scalars->SetName("Labels");
  for (size_t v = 0; v < values.size(); ++v)
    scalars->SetTuple1(static_cast<vtkIdType>(v), values[v]);
  vtkNew<vtkDoubleArray> seeds;
  seeds->SetName("Seeds");
  seeds->SetNumberOfComponents(3);
  for (const auto& s : atlas.Seeds())
    seeds->InsertNextTuple(s.data());
  output->GetFieldData()->AddArray(seeds);
  std::ostringstream params;
  params << "NumberOfLabels=" << this->NumberOfLabels << " Dimensions=" << this->Dimensions[0] << ","
         << this->Dimensions[1] << "," << this->Dimensions[2] << " Spacing=" << this->Spacing[0] << ","
         << this->Spacing[1] << "," << this->Spacing[2] << " SheetWidth=" << this->SheetWidth
         << " NoiseFraction=" << this->NoiseFraction << " Seed=" << this->Seed << " OutputScalarType=" << type;
  amProvenance::Record(output, nullptr, "amSyntheticAtlasSource", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amSyntheticAtlasSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLabels: " << this->NumberOfLabels << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " " << this->Dimensions[2]
     << "\n";
  os << indent << "Spacing: " << this->Spacing[0] << " " << this->Spacing[1] << " " << this->Spacing[2] << " mm\n";
  os << indent << "SheetWidth: " << this->SheetWidth << " mm\n";
  os << indent << "NoiseFraction: " << this->NoiseFraction << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "OutputScalarType: " << this->OutputScalarType << "\n";
}
