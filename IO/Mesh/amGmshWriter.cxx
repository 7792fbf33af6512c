#include "amGmshWriter.h"

#include "amTextOutput.h"

#include "amAtomicFile.h"
#include "amTetraFaces.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(amGmshWriter);

namespace
{
/// A box (min x y z, max x y z) around the given nodes of the grid, as $Entities wants it.
template<typename Ids>
void Grow(std::array<double, 6>& box, vtkUnstructuredGrid* grid, const Ids& ids)
{
  for (vtkIdType id : ids)
  {
    const double* x = grid->GetPoint(id);
    for (int d = 0; d < 3; ++d)
    {
      box[d] = std::min(box[d], x[d]);
      box[3 + d] = std::max(box[3 + d], x[d]);
    }
  }
}

constexpr std::array<double, 6> EmptyBox = { 1e300, 1e300, 1e300, -1e300, -1e300, -1e300 };

/// Cells grouped by region (the entity blocks).
using Regions = std::map<long long, std::vector<vtkIdType>>;
/// Interface and boundary triangles, one physical surface per pair of regions: the Medit writer's
/// references (1000 * higher + lower, 0 outside), so both formats name a surface alike. Each holds
/// its triangles and its (higher, lower) regions.
using Surfaces = std::map<long long, std::pair<std::vector<std::array<vtkIdType, 3>>, std::array<long long, 2>>>;

/// Checks every point and cell and groups the tetrahedra by region; the problem, or "".
std::string GroupByRegion(vtkUnstructuredGrid* grid, vtkDataArray* regionArray, Regions& byRegion)
{
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    const double* x = grid->GetPoint(i);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      return "point " + std::to_string(i) + " has a non-finite coordinate.";
  }
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
      return "cell " + std::to_string(c) + " has VTK type " + std::to_string(grid->GetCellType(c)) +
        "; only tetrahedra are written.";
    const double r = regionArray ? regionArray->GetComponent(c, 0) : 1.0;
    if (!(r >= 1 && r == std::floor(r)))
    {
      std::ostringstream why;
      why << "cell " << c << " has region " << r << "; Gmsh physical tags must be positive whole numbers.";
      return why.str();
    }
    byRegion[static_cast<long long>(r)].push_back(c);
  }
  return "";
}

Surfaces FindSurfaces(vtkUnstructuredGrid* grid, vtkDataArray* regionArray)
{
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  std::vector<double> points(3 * static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
    grid->GetPoint(i, &points[3 * i]);
  std::vector<std::array<vtkIdType, 4>> tets(static_cast<size_t>(nc));
  std::vector<int> labels(static_cast<size_t>(nc));
  for (vtkIdType c = 0; c < nc; ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    std::copy(ids, ids + 4, tets[c].begin());
    labels[c] = regionArray ? static_cast<int>(regionArray->GetComponent(c, 0)) : 1;
  }
  Surfaces surfaces;
  for (const auto& f : amTetraFaces::Find(points.data(), tets, labels.data()))
  {
    const long long lower = f.Second == amTetraFaces::Outside() ? 0 : f.Second;
    auto& group = surfaces[1000LL * f.First + lower];
    group.first.push_back(f.Points);
    group.second = { f.First, lower };
  }
  return surfaces;
}

/// The organ's name where the mesh carries its label map's "LabelNames" (indexed by label).
void WritePhysicalNames(amTextOutput& out, vtkUnstructuredGrid* grid, const Regions& byRegion, const Surfaces& surfaces)
{
  out << "$PhysicalNames\n" << byRegion.size() + surfaces.size() << "\n";
  auto* names = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("LabelNames"));
  auto nameOf = [&](long long label) {
    std::string name = label == 0 ? "Outside" : "Region " + std::to_string(label);
    if (label > 0 && names && label < names->GetNumberOfValues() && !names->GetValue(label).empty())
      name = names->GetValue(label);
    name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
    return name;
  };
  for (const auto& kv : surfaces)
    out << "2 " << kv.first << " \"" << nameOf(kv.second.second[0]) << " | " << nameOf(kv.second.second[1]) << "\"\n";
  for (const auto& kv : byRegion)
    out << "3 " << kv.first << " \"" << nameOf(kv.first) << "\"\n";
  out << "$EndPhysicalNames\n";
}

/// One surface entity per pair of regions and one volume entity per region, each tagged like its
/// physical group; each volume lists its bounding surfaces.
void WriteEntities(amTextOutput& out, vtkUnstructuredGrid* grid, const Regions& byRegion, const Surfaces& surfaces)
{
  out << "$Entities\n0 0 " << surfaces.size() << " " << byRegion.size() << "\n";
  for (const auto& kv : surfaces)
  {
    std::array<double, 6> box = EmptyBox;
    for (const auto& t : kv.second.first)
      Grow(box, grid, t);
    out << kv.first;
    for (double b : box)
      out << " " << b;
    out << " 1 " << kv.first << " 0\n";
  }
  for (const auto& kv : byRegion)
  {
    std::array<double, 6> box = EmptyBox;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c : kv.second)
    {
      grid->GetCellPoints(c, ids);
      Grow(box, grid, std::vector<vtkIdType>(ids->begin(), ids->end()));
    }
    out << kv.first;
    for (double b : box)
      out << " " << b;
    // Each interface the volume has a side of, negative where the surface's normal points into it
    // (it is the lower region).
    std::vector<long long> bounding;
    for (const auto& surface : surfaces)
      if (surface.second.second[0] == kv.first)
        bounding.push_back(surface.first);
      else if (surface.second.second[1] == kv.first)
        bounding.push_back(-surface.first);
    out << " 1 " << kv.first << " " << static_cast<long long>(bounding.size());
    for (long long b : bounding)
      out << " " << b;
    out << "\n";
  }
  out << "$EndEntities\n";
}

/// All nodes in one block, classified on the first volume.
void WriteNodes(amTextOutput& out, vtkUnstructuredGrid* grid, long long firstVolume)
{
  const vtkIdType np = grid->GetNumberOfPoints();
  out << "$Nodes\n1 " << np << " 1 " << np << "\n3 " << firstVolume << " 0 " << np << "\n";
  for (vtkIdType i = 0; i < np; ++i)
    out << i + 1 << "\n";
  for (vtkIdType i = 0; i < np; ++i)
  {
    const double* x = grid->GetPoint(i);
    out << x[0] << " " << x[1] << " " << x[2] << "\n";
  }
  out << "$EndNodes\n";
}

/// The tetrahedra region by region (tagged by their cell ids), then the surfaces' triangles.
void WriteElements(amTextOutput& out, vtkUnstructuredGrid* grid, const Regions& byRegion, const Surfaces& surfaces,
  const std::function<void(double)>& progress)
{
  const vtkIdType nc = grid->GetNumberOfCells();
  vtkIdType triangles = 0;
  for (const auto& kv : surfaces)
    triangles += static_cast<vtkIdType>(kv.second.first.size());
  const vtkIdType total = nc + triangles;
  out << "$Elements\n" << byRegion.size() + surfaces.size() << " " << total << " 1 " << total << "\n";
  vtkIdType done = 0;
  for (const auto& kv : byRegion)
  {
    out << "3 " << kv.first << " 4 " << kv.second.size() << "\n";
    for (vtkIdType c : kv.second)
    {
      vtkIdType n;
      const vtkIdType* ids;
      grid->GetCellPoints(c, n, ids);
      out << c + 1 << " " << ids[0] + 1 << " " << ids[1] + 1 << " " << ids[2] + 1 << " " << ids[3] + 1 << "\n";
      if (++done % 65536 == 0)
        progress(static_cast<double>(done) / nc);
    }
  }
  vtkIdType tag = nc;
  for (const auto& kv : surfaces)
  {
    out << "2 " << kv.first << " 2 " << kv.second.first.size() << "\n";
    for (const auto& t : kv.second.first)
      out << ++tag << " " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  }
  out << "$EndElements\n";
}
}

amGmshWriter::amGmshWriter()
  : FileName(nullptr)
  , RegionArrayName(nullptr)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(0);
  this->SetRegionArrayName("Region");
  this->WriteInterfaces = 1;
}

amGmshWriter::~amGmshWriter()
{
  this->SetFileName(nullptr);
  this->SetRegionArrayName(nullptr);
}

int amGmshWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

vtkTypeBool amGmshWriter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
    return this->WriteData(vtkDataObject::GetData(inputVector[0], 0));
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int amGmshWriter::Write()
{
  this->LastWriteOk = false;
  this->Modified();
  this->Update();
  return this->LastWriteOk ? 1 : 0;
}

int amGmshWriter::WriteData(vtkDataObject* data)
{
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  const std::string target = this->FileName;
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("Cannot write '" << target << "': the input has no tetrahedra.");
    return 0;
  }
  vtkDataArray* regionArray = this->RegionArrayName ? grid->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  Regions byRegion;
  std::string why = GroupByRegion(grid, regionArray, byRegion);
  if (!why.empty())
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why);
    return 0;
  }
  Surfaces surfaces;
  if (this->WriteInterfaces)
  {
    if (byRegion.rbegin()->first > 999)
      vtkWarningMacro("'" << target << "': regions beyond 999 leave no room for the interface tags (1000 * higher + "
                          << "lower); no surface groups are written.");
    else
      surfaces = FindSurfaces(grid, regionArray);
  }

  amAtomicFile file(target);
  if (!file.CanWrite(why))
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why << ".");
    return 0;
  }
  {
    std::ofstream stream(file.TemporaryPath());
    amTextOutput out(stream);
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    WritePhysicalNames(out, grid, byRegion, surfaces);
    WriteEntities(out, grid, byRegion, surfaces);
    WriteNodes(out, grid, byRegion.begin()->first);
    WriteElements(out, grid, byRegion, surfaces, [this](double f) { this->UpdateProgress(f); });
    if (!out.Flush())
    {
      vtkErrorMacro("Cannot write '" << target << "': output error (disk full?).");
      return 0;
    }
  }
  if (!file.Commit(why))
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why);
    return 0;
  }
  this->UpdateProgress(1.0);
  this->LastWriteOk = true;
  return 1;
}

void amGmshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)") << "\n";
  os << indent << "WriteInterfaces: " << this->WriteInterfaces << "\n";
}
