#include "amXdmfWriter.h"

#include "amXdmfGrid.h"

#include "amAtomicFile.h"
#include "amTetraFaces.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(amXdmfWriter);

amXdmfWriter::amXdmfWriter()
  : FileName(nullptr)
  , RegionArrayName(nullptr)
  , HeavyDataFormat(HDF5)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(0);
  this->SetRegionArrayName("Region");
}

amXdmfWriter::~amXdmfWriter()
{
  this->SetFileName(nullptr);
  this->SetRegionArrayName(nullptr);
}

int amXdmfWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

vtkTypeBool amXdmfWriter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
    return this->WriteData(vtkDataObject::GetData(inputVector[0], 0));
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int amXdmfWriter::Write()
{
  this->LastWriteOk = false;
  this->Modified();
  this->Update();
  return this->LastWriteOk ? 1 : 0;
}

namespace
{
/// The path without its ".xdmf".
std::string Stem(const std::string& path)
{
  const std::string ending = ".xdmf";
  const bool has = path.size() > ending.size() && path.compare(path.size() - ending.size(), ending.size(), ending) == 0;
  return has ? path.substr(0, path.size() - ending.size()) : path;
}

/// The tetrahedra, their regions, the points they use (renumbered in their order, -1 unused) and
/// every point's coordinates.
struct Tetrahedra
{
  std::vector<std::array<vtkIdType, 4>> Tets;
  std::vector<int> Labels;
  std::vector<vtkIdType> Number;
  std::vector<double> Points;
  vtkIdType Used = 0;
};

/// The grid's tetrahedra checked and gathered; the problem, or "".
std::string ReadTetrahedra(vtkUnstructuredGrid* grid, vtkDataArray* regions, Tetrahedra& in)
{
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  in.Tets.resize(static_cast<std::size_t>(nc));
  in.Labels.assign(static_cast<std::size_t>(nc), 1);
  in.Number.assign(np, -1);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
      return "cell " + std::to_string(c) + " has VTK type " + std::to_string(grid->GetCellType(c)) +
        "; only tetrahedra are written.";
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    std::copy(ids, ids + 4, in.Tets[c].begin());
    for (int a = 0; a < 4; ++a)
      in.Number[ids[a]] = 0;
    if (regions)
    {
      const double r = regions->GetComponent(c, 0);
      if (!(r == std::floor(r) && std::fabs(r) < 2e9))
      {
        std::ostringstream why;
        why << "cell " << c << " has region " << r << ", not a whole number.";
        return why.str();
      }
      in.Labels[c] = static_cast<int>(r);
    }
  }
  in.Points.resize(3 * static_cast<std::size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double* x = &in.Points[3 * i];
    grid->GetPoint(i, x);
    if (in.Number[i] < 0)
      continue;
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      return "point " + std::to_string(i) + " has a non-finite coordinate.";
    in.Number[i] = in.Used++;
  }
  return "";
}

/// Each region's and each interface's name (the organ's, where the mesh carries its label map's
/// "LabelNames"), without the characters XML would have to escape.
std::map<long long, std::string> TagNames(
  vtkUnstructuredGrid* grid, const std::vector<int>& labels, const std::vector<amTetraFaces::Face>& faces)
{
  auto* names = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("LabelNames"));
  auto nameOf = [&](long long label) {
    std::string name = label == 0 ? "Outside" : "Region " + std::to_string(label);
    if (label > 0 && names && label < names->GetNumberOfValues() && !names->GetValue(label).empty())
      name = names->GetValue(label);
    std::string clean;
    for (char ch : name)
      if (ch != '"' && ch != '<' && ch != '>' && ch != '&')
        clean += ch;
    return clean;
  };
  std::map<long long, std::string> tagNames;
  for (int l : labels)
    tagNames[l] = nameOf(l);
  for (const auto& f : faces)
  {
    const long long lower = f.Second == amTetraFaces::Outside() ? 0 : f.Second;
    tagNames[1000LL * f.First + lower] = nameOf(f.First) + " | " + nameOf(lower);
  }
  return tagNames;
}
}

std::string amXdmfWriter::HeavyDataFileName(const std::string& path)
{
  return Stem(path) + ".h5";
}

std::string amXdmfWriter::FacetsFileName(const std::string& path)
{
  return Stem(path) + "_facets.xdmf";
}

int amXdmfWriter::WriteData(vtkDataObject* data)
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
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  vtkDataArray* regions = this->RegionArrayName ? grid->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  Tetrahedra in;
  const std::string problem = ReadTetrahedra(grid, regions, in);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot write '" << target << "': " << problem);
    return 0;
  }
  const auto& tets = in.Tets;
  const auto& labels = in.Labels;
  const auto& number = in.Number;
  const auto& xyz = in.Points;
  const vtkIdType used = in.Used;
  const std::vector<amTetraFaces::Face> faces = amTetraFaces::Find(xyz.data(), tets, labels.data());
  const std::map<long long, std::string> tagNames = TagNames(grid, labels, faces);

  // Two files, each one grid (as meshio and FEniCSx's XDMFFile read them): the mesh with its cell
  // tags, and the facets with theirs, on the same points.
  std::vector<double> geometry;
  geometry.reserve(3 * static_cast<std::size_t>(used));
  for (vtkIdType i = 0; i < np; ++i)
    if (number[i] >= 0)
      geometry.insert(geometry.end(), &xyz[3 * i], &xyz[3 * i] + 3);
  amXdmfGrid mesh{ "mesh", "Tetrahedron", 4, {}, &geometry, {}, tagNames };
  mesh.Topology.reserve(4 * tets.size());
  for (const auto& t : tets)
    for (int a = 0; a < 4; ++a)
      mesh.Topology.push_back(number[t[a]]);
  mesh.Attributes.push_back({ "cell_tags", 1, std::vector<std::int64_t>(labels.begin(), labels.end()), {} });
  // The fibres and sheets where the mesh has them (Ventricular Fibres), after the tags: FEniCSx's
  // read_meshtags takes a grid's first attribute.
  for (const char* name : { "Fibers", "Sheets" })
  {
    vtkDataArray* vectors = grid->GetCellData()->GetArray(name);
    if (!vectors || vectors->GetNumberOfComponents() != 3)
      continue;
    amXdmfGrid::Attribute a{ name, 3, {}, std::vector<double>(3 * static_cast<std::size_t>(nc)) };
    for (vtkIdType c = 0; c < nc; ++c)
      vectors->GetTuple(c, &a.Reals[3 * c]);
    mesh.Attributes.push_back(std::move(a));
  }
  amXdmfGrid facets{ "facet_tags", "Triangle", 3, {}, &geometry, {}, tagNames };
  amXdmfGrid::Attribute facetTags{ "facet_tags", 1, {}, {} };
  for (const auto& f : faces)
  {
    for (int a = 0; a < 3; ++a)
      facets.Topology.push_back(number[f.Points[a]]);
    facetTags.Integers.push_back(1000LL * f.First + (f.Second == amTetraFaces::Outside() ? 0 : f.Second));
  }
  facets.Attributes.push_back(std::move(facetTags));

  const std::string facetsTarget = FacetsFileName(target);
  const bool hdf5 = this->HeavyDataFormat == HDF5;
  amAtomicFile meshFile(target), facetsFile(facetsTarget), meshData(HeavyDataFileName(target)),
    facetsData(HeavyDataFileName(facetsTarget));
  std::string why;
  if (!meshFile.CanWrite(why) || !facetsFile.CanWrite(why))
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why << ".");
    return 0;
  }
  auto nameOfFile = [](const std::string& path) { return path.substr(path.find_last_of('/') + 1); };
  struct Part
  {
    const amXdmfGrid& Grid;
    amAtomicFile& Text;
    amAtomicFile& Data;
  };
  for (const Part& part : { Part{ mesh, meshFile, meshData }, Part{ facets, facetsFile, facetsData } })
  {
    std::string xdmf, h5;
    if (!part.Grid.Make(hdf5 ? nameOfFile(part.Data.TargetPath()) : std::string(), xdmf, h5, why) ||
      (hdf5 && !part.Data.WriteTemporary(h5, why)) || !part.Text.WriteTemporary(xdmf, why))
    {
      vtkErrorMacro("Cannot write '" << part.Text.TargetPath() << "': " << why << ".");
      return 0;
    }
    this->UpdateProgress(&part.Grid == &mesh ? 0.6 : 0.9);
  }
  // The heavy data first: an .xdmf never names an .h5 that is not there.
  if ((hdf5 && (!meshData.Commit(why) || !facetsData.Commit(why))) || !meshFile.Commit(why) || !facetsFile.Commit(why))
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why);
    return 0;
  }
  this->UpdateProgress(1.0);
  this->LastWriteOk = true;
  return 1;
}

void amXdmfWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)") << "\n";
  os << indent << "HeavyDataFormat: " << (this->HeavyDataFormat == HDF5 ? "HDF5" : "XML") << "\n";
}
