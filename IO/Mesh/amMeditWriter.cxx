#include "amMeditWriter.h"

#include "amAtomicFile.h"
#include "amMeditFormat.h"
#include "amTetraFaces.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(amMeditWriter);

namespace
{
/// The cell blocks, keyed by VTK cell type (written in Medit's order).
using Blocks = std::map<int, amMeditFormat::Block>;

/// The points and their references; the problem, or "".
std::string GatherPoints(vtkPointSet* input, vtkDataArray* pointRefs, amMeditFormat::Mesh& mesh)
{
  const vtkIdType np = input->GetNumberOfPoints();
  mesh.Points.resize(static_cast<size_t>(np) * 3);
  mesh.PointRefs.assign(static_cast<size_t>(np), 0);
  for (vtkIdType i = 0; i < np; ++i)
  {
    input->GetPoint(i, &mesh.Points[3 * i]);
    for (int d = 0; d < 3; ++d)
      if (!std::isfinite(mesh.Points[3 * i + d]))
        return "point " + std::to_string(i) + " has a non-finite coordinate.";
  }
  if (pointRefs)
    for (vtkIdType i = 0; i < np; ++i)
      mesh.PointRefs[i] = static_cast<int>(pointRefs->GetComponent(i, 0));
  return "";
}

/// Every cell into the block of its type, with its region as reference; vertices are dropped.
std::string GatherCells(vtkPointSet* input, vtkDataArray* regions, Blocks& blocks)
{
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    const int type = input->GetCellType(c);
    const char* keyword = nullptr;
    switch (type)
    {
      case VTK_VERTEX:
      case VTK_POLY_VERTEX:
      case VTK_EMPTY_CELL:
        continue;
      case VTK_LINE:
        keyword = "Edges";
        break;
      case VTK_TRIANGLE:
        keyword = "Triangles";
        break;
      case VTK_QUAD:
        keyword = "Quadrilaterals";
        break;
      case VTK_TETRA:
        keyword = "Tetrahedra";
        break;
      case VTK_HEXAHEDRON:
        keyword = "Hexahedra";
        break;
      default:
        return "cell " + std::to_string(c) + " has VTK type " + std::to_string(type) +
          ", which Medit cannot hold (lines, triangles, quads, tetrahedra, hexahedra only).";
    }
    auto& b = blocks[type];
    b.Keyword = keyword;
    b.NodesPerCell = amMeditFormat::NodesOf(keyword);
    input->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      b.Connectivity.push_back(ids->GetId(k));
    b.Refs.push_back(regions ? static_cast<int>(regions->GetComponent(c, 0)) : 0);
  }
  return "";
}

/// The interface and boundary triangles of the tetrahedra, referenced 1000 * higher + lower (0
/// outside); false (nothing added) when a region lies outside 0-999.
bool AddInterfaces(Blocks& blocks, const amMeditFormat::Mesh& mesh)
{
  const auto& tetBlock = blocks[VTK_TETRA];
  std::vector<std::array<vtkIdType, 4>> tets(tetBlock.Refs.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    for (int k = 0; k < 4; ++k)
      tets[t][k] = static_cast<vtkIdType>(tetBlock.Connectivity[4 * t + k]);
    if (tetBlock.Refs[t] < 0 || tetBlock.Refs[t] > 999)
      return false;
  }
  amMeditFormat::Block b;
  b.Keyword = "Triangles";
  b.NodesPerCell = 3;
  for (const auto& f : amTetraFaces::Find(mesh.Points.data(), tets, tetBlock.Refs.data()))
  {
    b.Connectivity.insert(b.Connectivity.end(), f.Points.begin(), f.Points.end());
    b.Refs.push_back(1000 * f.First + (f.Second == amTetraFaces::Outside() ? 0 : f.Second));
  }
  blocks[VTK_TRIANGLE] = std::move(b);
  return true;
}

/// The point-data array as the .sol's field (scalar, vector or symmetric tensor); the problem, or "".
std::string GatherSolution(vtkPointSet* input, const char* name, amMeditFormat::Mesh& mesh)
{
  vtkDataArray* a = input->GetPointData()->GetArray(name);
  if (!a)
    return std::string("no point-data array '") + name + "'.";
  const int k = a->GetNumberOfComponents();
  if (k != 1 && k != 3 && k != 6)
    return std::string("array '") + name + "' has " + std::to_string(k) + " components (1, 3 or 6 expected).";
  amMeditFormat::Field field;
  field.Type = k == 1 ? 1 : k == 3 ? 2 : 3;
  const vtkIdType np = input->GetNumberOfPoints();
  field.Values.resize(static_cast<size_t>(np) * k);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double t[9];
    a->GetTuple(i, t);
    double* v = &field.Values[static_cast<size_t>(i) * k];
    if (k == 6)
      amMeditFormat::VTKToMeditTensor(t, v);
    else
      for (int j = 0; j < k; ++j)
        v[j] = t[j];
    for (int j = 0; j < k; ++j)
      if (!std::isfinite(v[j]))
        return "value at point " + std::to_string(i) + " is not finite.";
  }
  mesh.Fields.push_back(std::move(field));
  return "";
}

/// The .mesh (and the .sol beside it), each written whole or not at all; the problem, or "".
std::string WriteFiles(const amMeditFormat::Mesh& mesh, const std::string& target, const std::string& solTarget)
{
  amAtomicFile meshFile(target);
  std::string why;
  if (!meshFile.CanWrite(why))
    return "Cannot write '" + target + "': " + why + ".";
  {
    std::ofstream out(meshFile.TemporaryPath());
    if (!out || !amMeditFormat::WriteMesh(out, mesh) || !(out.flush()))
      return "Cannot write '" + target + "': output error (disk full?).";
  }
  if (!solTarget.empty())
  {
    amAtomicFile solFile(solTarget);
    std::ofstream out(solFile.TemporaryPath());
    if (!out || !amMeditFormat::WriteSolution(out, mesh) || !(out.flush()))
      return "Cannot write '" + solTarget + "': output error (disk full?).";
    out.close();
    if (!solFile.Commit(why))
      return "Cannot write '" + solTarget + "': " + why;
  }
  if (!meshFile.Commit(why))
    return "Cannot write '" + target + "': " + why;
  return "";
}
}

amMeditWriter::amMeditWriter()
  : FileName(nullptr)
  , RegionArrayName(nullptr)
  , PointRefArrayName(nullptr)
  , SolutionArrayName(nullptr)
  , WriteInterfaces(1)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(0);
  this->SetRegionArrayName("Region");
  this->SetPointRefArrayName("Ref");
}

amMeditWriter::~amMeditWriter()
{
  this->SetFileName(nullptr);
  this->SetRegionArrayName(nullptr);
  this->SetPointRefArrayName(nullptr);
  this->SetSolutionArrayName(nullptr);
}

int amMeditWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

vtkTypeBool amMeditWriter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
    return this->WriteData(vtkDataObject::GetData(inputVector[0], 0));
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int amMeditWriter::Write()
{
  this->LastWriteOk = false;
  this->Modified();
  this->Update();
  return this->LastWriteOk ? 1 : 0;
}

int amMeditWriter::WriteData(vtkDataObject* data)
{
  this->LastWriteOk = false;
  vtkPointSet* input = vtkPointSet::SafeDownCast(data);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  const std::string target(this->FileName);
  if (!input)
  {
    vtkErrorMacro("Cannot write '" << target << "': the input is not a point set (polydata or unstructured grid).");
    return 0;
  }
  amMeditFormat::Mesh mesh;
  vtkDataArray* pointRefs =
    this->PointRefArrayName ? input->GetPointData()->GetArray(this->PointRefArrayName) : nullptr;
  vtkDataArray* regions = this->RegionArrayName ? input->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  Blocks blocks;
  std::string why = GatherPoints(input, pointRefs, mesh);
  if (why.empty())
    why = GatherCells(input, regions, blocks);
  if (!why.empty())
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why);
    return 0;
  }
  if (this->WriteInterfaces && blocks.count(VTK_TETRA) && !blocks.count(VTK_TRIANGLE) && !AddInterfaces(blocks, mesh))
    vtkWarningMacro("'" << target << "': the tetrahedra's regions are not all within 0-999, which the interface "
                        << "references (1000 * higher + lower) need; no interface triangles are written.");
  for (int type : { VTK_LINE, VTK_TRIANGLE, VTK_QUAD, VTK_TETRA, VTK_HEXAHEDRON })
    if (blocks.count(type))
      mesh.Blocks.push_back(std::move(blocks[type]));
  this->UpdateProgress(0.3);

  std::string solTarget;
  if (this->SolutionArrayName && *this->SolutionArrayName)
  {
    why = GatherSolution(input, this->SolutionArrayName, mesh);
    if (!why.empty())
    {
      vtkErrorMacro("Cannot write the solution of '" << target << "': " << why);
      return 0;
    }
    solTarget = amMeditFormat::SolutionPathFor(target);
  }
  why = WriteFiles(mesh, target, solTarget);
  if (!why.empty())
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  this->UpdateProgress(1.0);
  this->LastWriteOk = true;
  return 1;
}

void amMeditWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "WriteInterfaces: " << this->WriteInterfaces << "\n";
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)") << "\n";
  os << indent << "PointRefArrayName: " << (this->PointRefArrayName ? this->PointRefArrayName : "(none)") << "\n";
  os << indent << "SolutionArrayName: " << (this->SolutionArrayName ? this->SolutionArrayName : "(none)") << "\n";
}
