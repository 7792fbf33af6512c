#include "amCardiacLandmarks.h"

#include "Anatomy/amThoraxLandmarks.h"
#include "amInputCheck.h"
#include "amProvenance.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

vtkStandardNewMacro(amCardiacLandmarks);

amCardiacLandmarks::amCardiacLandmarks() = default;

amCardiacLandmarks::~amCardiacLandmarks() = default;

int amCardiacLandmarks::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

int amCardiacLandmarks::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  std::vector<unsigned char> labels;
  if (!scalars || !amInputCheck::LabelBytes(scalars, 255, labels, why))
  {
    vtkErrorMacro("The label map: " << why);
    return 0;
  }
  amThoraxLandmarks::Grid grid;
  input->GetDimensions(grid.N);
  const double* origin = input->GetOrigin();
  const double* spacing = input->GetSpacing();
  vtkMatrix3x3* direction = input->GetDirectionMatrix();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
      grid.Row[r][c] = direction->GetElement(r, c) * spacing[c];
    grid.Row[r][3] = origin[r];
  }
  this->UpdateProgress(0.1);
  const amThoraxLandmarks::Result found = amThoraxLandmarks::Find(grid, labels);
  if (!found.Problem.empty())
  {
    vtkErrorMacro("The landmarks cannot be found: " << found.Problem << ".");
    return 0;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkStringArray> names;
  names->SetName("Name");
  for (const auto& p : found.Points)
  {
    const vtkIdType id = points->InsertNextPoint(p.X.data());
    vertices->InsertNextCell(1, &id);
    names->InsertNextValue(p.Name);
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(names);
  vtkNew<vtkDoubleArray> axis;
  axis->SetName("LongAxis");
  axis->SetNumberOfComponents(3);
  axis->InsertNextTuple(found.LongAxis.data());
  output->GetFieldData()->AddArray(axis);
  vtkNew<vtkDoubleArray> length;
  length->SetName("LongAxisLength");
  length->InsertNextValue(found.LongAxisLength);
  output->GetFieldData()->AddArray(length);
  amProvenance::Record(output, input, "CardiacLandmarks", "");
  this->UpdateProgress(1.0);
  return 1;
}

void amCardiacLandmarks::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
