#include "amSeedPointsSource.h"

#include "amProvenance.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(amSeedPointsSource);

amSeedPointsSource::amSeedPointsSource()
  : Positions{ 29.4, -24.1, -28.0, -15.0, -25.0, -28.0, 5.0, 40.0, 0.0, 5.0, -20.0, 30.0 }
  , Labels{ 6, 7, 8, 8 }
  , LabelArrayName(nullptr)
{
  this->SetNumberOfInputPorts(0);
  this->SetLabelArrayName("Label");
}

amSeedPointsSource::~amSeedPointsSource()
{
  this->SetLabelArrayName(nullptr);
}

void amSeedPointsSource::SetNumberOfSeeds(int n)
{
  const size_t size = 3 * static_cast<size_t>(std::max(0, n));
  if (size != this->Positions.size())
  {
    this->Positions.resize(size, 0.0);
    this->Modified();
  }
}

void amSeedPointsSource::SetSeedPosition(int i, double x, double y, double z)
{
  if (i < 0)
  {
    vtkErrorMacro("Seed index " << i << " is negative.");
    return;
  }
  if (3 * static_cast<size_t>(i) + 3 > this->Positions.size())
    this->SetNumberOfSeeds(i + 1);
  double* p = &this->Positions[3 * static_cast<size_t>(i)];
  if (p[0] != x || p[1] != y || p[2] != z)
  {
    p[0] = x;
    p[1] = y;
    p[2] = z;
    this->Modified();
  }
}

void amSeedPointsSource::SetNumberOfSeedLabels(int n)
{
  const size_t size = static_cast<size_t>(std::max(0, n));
  if (size != this->Labels.size())
  {
    this->Labels.resize(size, 1);
    this->Modified();
  }
}

void amSeedPointsSource::SetSeedLabel(int i, int label)
{
  if (i < 0)
  {
    vtkErrorMacro("Seed label index " << i << " is negative.");
    return;
  }
  if (static_cast<size_t>(i) >= this->Labels.size())
    this->SetNumberOfSeedLabels(i + 1);
  if (this->Labels[i] != label)
  {
    this->Labels[i] = label;
    this->Modified();
  }
}

int amSeedPointsSource::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const int n = this->GetNumberOfSeeds();
  if (static_cast<int>(this->Labels.size()) > n)
    vtkWarningMacro(<< this->Labels.size() << " seed labels for " << n << " seeds: the last " << this->Labels.size() - n
                    << " label(s) belong to no seed and are not used.");
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkIntArray> labels;
  labels->SetName(this->LabelArrayName && *this->LabelArrayName ? this->LabelArrayName : "Label");
  for (int i = 0; i < n; ++i)
  {
    const double* p = &this->Positions[3 * static_cast<size_t>(i)];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      vtkErrorMacro("Seed " << i << " is at (" << p[0] << ", " << p[1] << ", " << p[2] << "): not a position.");
      return 0;
    }
    const int label = i < static_cast<int>(this->Labels.size()) ? this->Labels[i] : i + 1;
    if (label < 1 || label > 255)
    {
      vtkErrorMacro("Seed " << i << " has label " << label << ": labels are 1..255 (0 is the background).");
      return 0;
    }
    const vtkIdType id = points->InsertNextPoint(p);
    vertices->InsertNextCell(1, &id);
    labels->InsertNextValue(label);
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(labels);
  std::ostringstream params;
  params << "Seeds=";
  for (int i = 0; i < n; ++i)
    params << (i ? ";" : "") << this->Positions[3 * i] << "," << this->Positions[3 * i + 1] << ","
           << this->Positions[3 * i + 2] << ":" << labels->GetValue(i);
  amProvenance::Record(output, nullptr, "amSeedPointsSource", params.str());
  return 1;
}

void amSeedPointsSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSeeds: " << this->GetNumberOfSeeds() << "\n";
  for (int i = 0; i < this->GetNumberOfSeeds(); ++i)
    os << indent << "  (" << this->Positions[3 * i] << ", " << this->Positions[3 * i + 1] << ", "
       << this->Positions[3 * i + 2] << ") label "
       << (i < static_cast<int>(this->Labels.size()) ? this->Labels[i] : i + 1) << "\n";
  os << indent << "LabelArrayName: " << (this->LabelArrayName ? this->LabelArrayName : "(none)") << "\n";
}
