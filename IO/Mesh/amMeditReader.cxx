#include "amMeditReader.h"

#include "amInputCheck.h"
#include "amMeditFormat.h"
#include "amProvenance.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <fstream>
#include <sys/stat.h>

vtkStandardNewMacro(amMeditReader);

namespace
{
int CellTypeOf(const std::string& keyword)
{
  if (keyword == "Edges")
    return VTK_LINE;
  if (keyword == "Triangles")
    return VTK_TRIANGLE;
  if (keyword == "Quadrilaterals")
    return VTK_QUAD;
  if (keyword == "Tetrahedra")
    return VTK_TETRA;
  return VTK_HEXAHEDRON;
}
}

amMeditReader::amMeditReader()
  : FileName(nullptr)
  , SolutionFileName(nullptr)
  , ReadSolution(true)
{
  this->SetNumberOfInputPorts(0);
}

amMeditReader::~amMeditReader()
{
  this->SetFileName(nullptr);
  this->SetSolutionFileName(nullptr);
}

int amMeditReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  const std::string path(this->FileName);
  std::string why;
  if (!amInputCheck::ReadableFile(path, false, why))
  {
    vtkErrorMacro("Cannot read the Medit mesh: " << why);
    return 0;
  }
  std::ifstream in(path);
  if (!in)
  {
    vtkErrorMacro("Cannot open Medit mesh '" << path << "'.");
    return 0;
  }
  amMeditFormat::Mesh mesh;
  std::string error;
  if (!amMeditFormat::ReadMesh(in, mesh, error))
  {
    vtkErrorMacro("Cannot read Medit mesh '" << path << "': " << error << ".");
    return 0;
  }
  this->UpdateProgress(0.6);

  std::string solPath = this->SolutionFileName ? this->SolutionFileName : "";
  bool solRequired = !solPath.empty();
  if (solPath.empty())
    solPath = amMeditFormat::SolutionPathFor(path);
  struct stat st;
  if (this->ReadSolution && (solRequired || ::stat(solPath.c_str(), &st) == 0))
  {
    std::ifstream sin(solPath);
    if (!sin)
    {
      vtkErrorMacro("Cannot open Medit solution '" << solPath << "'.");
      return 0;
    }
    if (!amMeditFormat::ReadSolution(sin, mesh, error))
    {
      vtkErrorMacro("Cannot read Medit solution '" << solPath << "': " << error << ".");
      return 0;
    }
  }

  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  const vtkIdType np = static_cast<vtkIdType>(mesh.PointRefs.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(np);
  for (vtkIdType i = 0; i < np; ++i)
    points->SetPoint(i, &mesh.Points[3 * i]);
  output->SetPoints(points);
  vtkNew<vtkIntArray> pointRefs;
  pointRefs->SetName("Ref");
  pointRefs->SetNumberOfTuples(np);
  for (vtkIdType i = 0; i < np; ++i)
    pointRefs->SetValue(i, mesh.PointRefs[i]);
  output->GetPointData()->AddArray(pointRefs);

  vtkIdType nc = 0;
  for (const auto& b : mesh.Blocks)
    nc += static_cast<vtkIdType>(b.Refs.size());
  output->Allocate(nc);
  vtkNew<vtkIntArray> regions;
  regions->SetName("Region");
  regions->SetNumberOfTuples(nc);
  vtkIdType c = 0;
  for (const auto& b : mesh.Blocks)
  {
    const int type = CellTypeOf(b.Keyword);
    vtkIdType ids[8];
    for (size_t i = 0; i < b.Refs.size(); ++i)
    {
      for (int k = 0; k < b.NodesPerCell; ++k)
        ids[k] = static_cast<vtkIdType>(b.Connectivity[i * b.NodesPerCell + k]);
      output->InsertNextCell(type, b.NodesPerCell, ids);
      regions->SetValue(c++, b.Refs[i]);
    }
  }
  output->GetCellData()->AddArray(regions);

  for (size_t f = 0; f < mesh.Fields.size(); ++f)
  {
    const auto& field = mesh.Fields[f];
    const int nc3 = field.Components(mesh.Dimension);
    vtkNew<vtkDoubleArray> a;
    std::string name = field.Type == 3 ? "Metric" : "Solution";
    if (mesh.Fields.size() > 1)
      name += std::to_string(f);
    a->SetName(name.c_str());
    const int outComps = field.Type == 1 ? 1 : field.Type == 2 ? 3 : 6;
    a->SetNumberOfComponents(outComps);
    a->SetNumberOfTuples(np);
    for (vtkIdType i = 0; i < np; ++i)
    {
      const double* v = &field.Values[static_cast<size_t>(i) * nc3];
      double t[6] = { 0, 0, 0, 0, 0, 0 };
      if (field.Type == 3 && mesh.Dimension == 3)
        amMeditFormat::MeditToVTKTensor(v, t);
      else if (field.Type == 3)
      {
        t[0] = v[0];
        t[1] = v[2];
        t[3] = v[1];
      }
      else
        for (int j = 0; j < nc3; ++j)
          t[j] = v[j];
      a->SetTypedTuple(i, t);
    }
    output->GetPointData()->AddArray(a);
  }
  amProvenance::Record(output, nullptr, "amMeditReader", "FileName=" + path);
  this->UpdateProgress(1.0);
  return 1;
}

void amMeditReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "SolutionFileName: " << (this->SolutionFileName ? this->SolutionFileName : "(none)") << "\n";
  os << indent << "ReadSolution: " << this->ReadSolution << "\n";
}
