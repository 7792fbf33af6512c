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
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  // The points the tetrahedra use, renumbered in their order.
  std::vector<vtkIdType> number(np, -1);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
    {
      vtkErrorMacro("Cannot write '" << base << ".elem': cell " << c << " has VTK type " << grid->GetCellType(c)
                                     << "; only tetrahedra are written.");
      return 0;
    }
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    for (int a = 0; a < 4; ++a)
      number[ids[a]] = 0;
  }
  vtkIdType used = 0;
  for (vtkIdType i = 0; i < np; ++i)
    if (number[i] == 0)
    {
      const double* x = grid->GetPoint(i);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      {
        vtkErrorMacro("Cannot write '" << base << ".pts': point " << i << " has a non-finite coordinate.");
        return 0;
      }
      number[i] = used++;
    }
  vtkDataArray* regions = this->RegionArrayName ? grid->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  vtkDataArray* fibres = this->FiberArrayName ? grid->GetCellData()->GetArray(this->FiberArrayName) : nullptr;
  vtkDataArray* sheets = this->SheetArrayName ? grid->GetCellData()->GetArray(this->SheetArrayName) : nullptr;
  for (vtkDataArray* a : { fibres, sheets })
    if (a && a->GetNumberOfComponents() != 3)
    {
      vtkErrorMacro("Cannot write '" << base << ".lon': the cell array '" << a->GetName() << "' has "
                                     << a->GetNumberOfComponents() << " components, not 3.");
      return 0;
    }
  if (!fibres)
    sheets = nullptr;

  // Every file's content, written to temporaries first and renamed together.
  struct Part
  {
    std::string Target;
    std::function<void(amTextOutput&)> Fill;
  };
  std::vector<Part> parts;
  const double scale = this->CoordinateScale;
  parts.push_back({ base + ".pts", [&](amTextOutput& out) {
                     out << used << "\n";
                     for (vtkIdType i = 0; i < np; ++i)
                       if (number[i] >= 0)
                       {
                         const double* x = grid->GetPoint(i);
                         out << x[0] * scale << " " << x[1] * scale << " " << x[2] * scale << "\n";
                       }
                   } });
  parts.push_back({ base + ".elem", [&](amTextOutput& out) {
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
    parts.push_back({ base + ".lon", [&](amTextOutput& out) {
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

  // Tagged surfaces: one .surf and .vtx per tag.
  vtkPolyData* surfaces = vtkPolyData::SafeDownCast(surfaceData);
  std::map<long long, std::vector<std::array<vtkIdType, 3>>> byTag;
  std::map<long long, std::string> tagNames;
  if (surfaces)
  {
    vtkDataArray* tags =
      this->SurfaceTagArrayName ? surfaces->GetCellData()->GetArray(this->SurfaceTagArrayName) : nullptr;
    vtkDataArray* ids = surfaces->GetPointData()->GetArray("InputPointId");
    if (!tags || !ids)
    {
      vtkErrorMacro("Cannot write the surfaces of '" << base << "': they need cell data '"
                                                     << (this->SurfaceTagArrayName ? this->SurfaceTagArrayName : "")
                                                     << "' and point data InputPointId.");
      return 0;
    }
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
      {
        vtkErrorMacro("Cannot write the surfaces of '" << base << "': triangle " << c
                                                       << " is not a triangle of the mesh's points.");
        return 0;
      }
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
  }
  for (const auto& kv : byTag)
  {
    const std::string name = tagNames.count(kv.first) ? tagNames[kv.first] : "tag" + std::to_string(kv.first);
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

  std::vector<std::unique_ptr<amAtomicFile>> files;
  for (std::size_t k = 0; k < parts.size(); ++k)
  {
    files.push_back(std::make_unique<amAtomicFile>(parts[k].Target));
    std::string why;
    if (!files.back()->CanWrite(why))
    {
      vtkErrorMacro("Cannot write '" << parts[k].Target << "': " << why << ".");
      return 0;
    }
    std::ofstream stream(files.back()->TemporaryPath());
    amTextOutput out(stream);
    parts[k].Fill(out);
    if (!out.Flush())
    {
      vtkErrorMacro("Cannot write '" << parts[k].Target << "': output error (disk full?).");
      return 0;
    }
    this->UpdateProgress(0.9 * (k + 1) / parts.size());
  }
  for (std::size_t k = 0; k < files.size(); ++k)
  {
    std::string why;
    if (!files[k]->Commit(why))
    {
      vtkErrorMacro("Cannot write '" << parts[k].Target << "': " << why);
      return 0;
    }
    this->Written.push_back(parts[k].Target);
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
