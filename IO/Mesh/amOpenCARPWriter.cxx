#include "amOpenCARPWriter.h"

#include "amTextOutput.h"

#include "amAtomicFile.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>

vtkStandardNewMacro(amOpenCARPWriter);

namespace
{
/// One file's name and the function that writes its content.
struct Part
{
  std::string Target;
  std::function<void(amTextOutput&)> Fill;
};
/// The tagged surfaces' triangles (in the written points' numbers), by tag.
using Tagged = std::map<long long, std::vector<std::array<vtkIdType, 3>>>;

/// The points the tetrahedra use, renumbered in their order (-1: unused); the problem, or "".
std::string NumberUsedPoints(
  vtkUnstructuredGrid* grid, const std::string& base, std::vector<vtkIdType>& number, vtkIdType& used)
{
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  number.assign(np, -1);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
      return "Cannot write '" + base + ".elem': cell " + std::to_string(c) + " has VTK type " +
        std::to_string(grid->GetCellType(c)) + "; only tetrahedra are written.";
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    for (int a = 0; a < 4; ++a)
      number[ids[a]] = 0;
  }
  used = 0;
  for (vtkIdType i = 0; i < np; ++i)
    if (number[i] == 0)
    {
      const double* x = grid->GetPoint(i);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
        return "Cannot write '" + base + ".pts': point " + std::to_string(i) + " has a non-finite coordinate.";
      number[i] = used++;
    }
  return "";
}

/// The .pts, .elem and (with fibres) .lon files.
void AddVolumeParts(std::vector<Part>& parts, const std::string& base, vtkUnstructuredGrid* grid,
  const std::vector<vtkIdType>& number, vtkIdType used, vtkDataArray* regions, vtkDataArray* fibres,
  vtkDataArray* sheets, double scale)
{
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  parts.push_back({ base + ".pts", [&number, grid, used, np, scale](amTextOutput& out) {
                     out << used << "\n";
                     for (vtkIdType i = 0; i < np; ++i)
                       if (number[i] >= 0)
                       {
                         const double* x = grid->GetPoint(i);
                         out << x[0] * scale << " " << x[1] * scale << " " << x[2] * scale << "\n";
                       }
                   } });
  parts.push_back({ base + ".elem", [&number, grid, regions, nc](amTextOutput& out) {
                     out << nc << "\n";
                     for (vtkIdType c = 0; c < nc; ++c)
                     {
                       vtkIdType n;
                       const vtkIdType* ids;
                       grid->GetCellPoints(c, n, ids);
                       const long long region = regions ? std::llround(regions->GetComponent(c, 0)) : 0;
                       out << "Tt " << number[ids[0]] << " " << number[ids[1]] << " " << number[ids[2]] << " "
                           << number[ids[3]] << " " << region << "\n";
                     }
                   } });
  if (fibres)
    parts.push_back({ base + ".lon", [fibres, sheets, nc](amTextOutput& out) {
                       out << (sheets ? 2 : 1) << "\n";
                       double f[3], s[3];
                       for (vtkIdType c = 0; c < nc; ++c)
                       {
                         fibres->GetTuple(c, f);
                         out << f[0] << " " << f[1] << " " << f[2];
                         if (sheets)
                         {
                           sheets->GetTuple(c, s);
                           out << " " << s[0] << " " << s[1] << " " << s[2];
                         }
                         out << "\n";
                       }
                     } });
}

/// The tagged surfaces' triangles by tag, and the tags' names (field data TagNames: "tag name");
/// the problem, or "".
std::string GatherSurfaces(vtkPolyData* surfaces, const char* tagArrayName, const std::string& base,
  const std::vector<vtkIdType>& number, Tagged& byTag, std::map<long long, std::string>& tagNames)
{
  vtkDataArray* tags = tagArrayName ? surfaces->GetCellData()->GetArray(tagArrayName) : nullptr;
  vtkDataArray* ids = surfaces->GetPointData()->GetArray("InputPointId");
  if (!tags || !ids)
    return "Cannot write the surfaces of '" + base + "': they need cell data '" + (tagArrayName ? tagArrayName : "") +
      "' and point data InputPointId.";
  const vtkIdType np = static_cast<vtkIdType>(number.size());
  for (vtkIdType c = 0; c < surfaces->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* pts;
    surfaces->GetCellPoints(c, n, pts);
    std::array<vtkIdType, 3> tri{};
    for (vtkIdType a = 0; a < 3 && n == 3; ++a)
    {
      const vtkIdType p = static_cast<vtkIdType>(ids->GetComponent(pts[a], 0));
      tri[a] = p >= 0 && p < np ? number[p] : -1;
    }
    if (n != 3 || tri[0] < 0 || tri[1] < 0 || tri[2] < 0)
      return "Cannot write the surfaces of '" + base + "': triangle " + std::to_string(c) +
        " is not a triangle of the mesh's points.";
    byTag[std::llround(tags->GetComponent(c, 0))].push_back(tri);
  }
  if (auto* names = vtkStringArray::SafeDownCast(surfaces->GetFieldData()->GetAbstractArray("TagNames")))
    for (vtkIdType k = 0; k < names->GetNumberOfValues(); ++k)
    {
      std::istringstream line(names->GetValue(k));
      long long tag;
      std::string name;
      if (line >> tag >> name)
        tagNames[tag] = name;
    }
  return "";
}

/// One .surf and one .vtx per tag.
void AddSurfaceParts(std::vector<Part>& parts, const std::string& base, const Tagged& byTag,
  const std::map<long long, std::string>& tagNames)
{
  for (const auto& kv : byTag)
  {
    const std::string name = tagNames.count(kv.first) ? tagNames.at(kv.first) : "tag" + std::to_string(kv.first);
    const auto* triangles = &kv.second;
    parts.push_back({ base + "." + name + ".surf", [triangles](amTextOutput& out) {
                       out << triangles->size() << "\n";
                       for (const auto& t : *triangles)
                         out << "Tr " << t[0] << " " << t[1] << " " << t[2] << "\n";
                     } });
    parts.push_back({ base + "." + name + ".vtx", [triangles](amTextOutput& out) {
                       std::vector<vtkIdType> nodes;
                       for (const auto& t : *triangles)
                         nodes.insert(nodes.end(), t.begin(), t.end());
                       std::sort(nodes.begin(), nodes.end());
                       nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
                       out << nodes.size() << "\nintra\n";
                       for (vtkIdType v : nodes)
                         out << v << "\n";
                     } });
  }
}

/// Every file written to its temporary first, then all renamed together; the problem, or "".
std::string WriteParts(
  const std::vector<Part>& parts, const std::function<void(double)>& progress, std::vector<std::string>& written)
{
  std::vector<std::unique_ptr<amAtomicFile>> files;
  for (std::size_t k = 0; k < parts.size(); ++k)
  {
    files.push_back(std::make_unique<amAtomicFile>(parts[k].Target));
    std::string why;
    if (!files.back()->CanWrite(why))
      return "Cannot write '" + parts[k].Target + "': " + why + ".";
    std::ofstream stream(files.back()->TemporaryPath());
    amTextOutput out(stream);
    parts[k].Fill(out);
    if (!out.Flush())
      return "Cannot write '" + parts[k].Target + "': output error (disk full?).";
    progress(0.9 * (k + 1) / parts.size());
  }
  for (std::size_t k = 0; k < files.size(); ++k)
  {
    std::string why;
    if (!files[k]->Commit(why))
      return "Cannot write '" + parts[k].Target + "': " + why;
    written.push_back(parts[k].Target);
  }
  return "";
}
}

amOpenCARPWriter::amOpenCARPWriter()
  : FileName(nullptr)
  , RegionArrayName(nullptr)
  , FiberArrayName(nullptr)
  , SheetArrayName(nullptr)
  , SurfaceTagArrayName(nullptr)
  , CoordinateScale(1000.0)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(0);
  this->SetRegionArrayName("Region");
  this->SetFiberArrayName("Fibers");
  this->SetSheetArrayName("Sheets");
  this->SetSurfaceTagArrayName("VentricularTag");
}

amOpenCARPWriter::~amOpenCARPWriter()
{
  this->SetFileName(nullptr);
  this->SetRegionArrayName(nullptr);
  this->SetFiberArrayName(nullptr);
  this->SetSheetArrayName(nullptr);
  this->SetSurfaceTagArrayName(nullptr);
}

int amOpenCARPWriter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

vtkTypeBool amOpenCARPWriter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
    return this->WriteData(vtkDataObject::GetData(inputVector[0], 0),
      inputVector[1]->GetNumberOfInformationObjects() ? vtkDataObject::GetData(inputVector[1], 0) : nullptr);
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int amOpenCARPWriter::Write()
{
  this->LastWriteOk = false;
  this->Modified();
  this->Update();
  return this->LastWriteOk ? 1 : 0;
}

std::string amOpenCARPWriter::BaseName(const std::string& path)
{
  for (const char* ending : { ".pts", ".elem", ".lon" })
  {
    const std::string e(ending);
    if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
      return path.substr(0, path.size() - e.size());
  }
  return path;
}

int amOpenCARPWriter::WriteData(vtkDataObject* data, vtkDataObject* surfaceData)
{
  this->Written.clear();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  const std::string base = BaseName(this->FileName);
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("Cannot write '" << base << ".pts': the input has no tetrahedra.");
    return 0;
  }
  std::vector<vtkIdType> number;
  vtkIdType used = 0;
  std::string why = NumberUsedPoints(grid, base, number, used);
  vtkDataArray* regions = this->RegionArrayName ? grid->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  vtkDataArray* fibres = this->FiberArrayName ? grid->GetCellData()->GetArray(this->FiberArrayName) : nullptr;
  vtkDataArray* sheets = this->SheetArrayName ? grid->GetCellData()->GetArray(this->SheetArrayName) : nullptr;
  for (vtkDataArray* a : { fibres, sheets })
    if (why.empty() && a && a->GetNumberOfComponents() != 3)
      why = "Cannot write '" + base + ".lon': the cell array '" + a->GetName() + "' has " +
        std::to_string(a->GetNumberOfComponents()) + " components, not 3.";
  if (!fibres)
    sheets = nullptr;
  Tagged byTag;
  std::map<long long, std::string> tagNames;
  if (why.empty())
    if (vtkPolyData* surfaces = vtkPolyData::SafeDownCast(surfaceData))
      why = GatherSurfaces(surfaces, this->SurfaceTagArrayName, base, number, byTag, tagNames);
  if (!why.empty())
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  std::vector<Part> parts;
  AddVolumeParts(parts, base, grid, number, used, regions, fibres, sheets, this->CoordinateScale);
  AddSurfaceParts(parts, base, byTag, tagNames);
  why = WriteParts(
    parts, [this](double f) { this->UpdateProgress(f); }, this->Written);
  if (!why.empty())
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  this->UpdateProgress(1.0);
  this->LastWriteOk = true;
  return 1;
}

void amOpenCARPWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "CoordinateScale: " << this->CoordinateScale << "\n";
}
