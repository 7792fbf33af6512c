#include "amXdmfWriter.h"

#include "amTextOutput.h"

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
#include <fstream>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(amXdmfWriter);

amXdmfWriter::amXdmfWriter()
  : FileName(nullptr)
  , RegionArrayName(nullptr)
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

std::string amXdmfWriter::FacetsFileName(const std::string& path)
{
  const std::string ending = ".xdmf";
  const bool has = path.size() > ending.size() && path.compare(path.size() - ending.size(), ending.size(), ending) == 0;
  return (has ? path.substr(0, path.size() - ending.size()) : path) + "_facets.xdmf";
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
  std::vector<std::array<vtkIdType, 4>> tets(static_cast<std::size_t>(nc));
  std::vector<int> labels(static_cast<std::size_t>(nc), 1);
  std::vector<vtkIdType> number(np, -1);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
    {
      vtkErrorMacro("Cannot write '" << target << "': cell " << c << " has VTK type " << grid->GetCellType(c)
                                     << "; only tetrahedra are written.");
      return 0;
    }
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    std::copy(ids, ids + 4, tets[c].begin());
    for (int a = 0; a < 4; ++a)
      number[ids[a]] = 0;
    if (regions)
    {
      const double r = regions->GetComponent(c, 0);
      if (!(r == std::floor(r) && std::fabs(r) < 2e9))
      {
        vtkErrorMacro("Cannot write '" << target << "': cell " << c << " has region " << r << ", not a whole number.");
        return 0;
      }
      labels[c] = static_cast<int>(r);
    }
  }
  std::vector<double> xyz(3 * static_cast<std::size_t>(np));
  vtkIdType used = 0;
  for (vtkIdType i = 0; i < np; ++i)
  {
    grid->GetPoint(i, &xyz[3 * i]);
    if (number[i] < 0)
      continue;
    if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2]))
    {
      vtkErrorMacro("Cannot write '" << target << "': point " << i << " has a non-finite coordinate.");
      return 0;
    }
    number[i] = used++;
  }
  const std::vector<amTetraFaces::Face> faces = amTetraFaces::Find(xyz.data(), tets, labels.data());
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

  // Two files, each one grid (as meshio and FEniCSx's XDMFFile read them): the mesh with its cell
  // tags, and the facets with theirs.
  const std::string facetsTarget = FacetsFileName(target);
  amAtomicFile meshFile(target), facetsFile(facetsTarget);
  std::string why;
  if (!meshFile.CanWrite(why) || !facetsFile.CanWrite(why))
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why << ".");
    return 0;
  }
  auto head = [&](amTextOutput& out, const char* grid, const char* topologyType, std::size_t count, int per) {
    out << "<?xml version=\"1.0\"?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<!-- Anatomesh: lengths in mm, patient frame LPS; tags: regions, 1000 x higher + lower per interface "
           "(0: outside) -->\n"
        << "<Xdmf Version=\"3.0\">\n  <Domain>\n    <Grid Name=\"" << grid << "\" GridType=\"Uniform\">\n";
    // The tags' names, as meshio reads field data (and Gmsh's physical names give them).
    out << "      <Information Name=\"Information\" Value=\"" << tagNames.size() << "\"><![CDATA[<main>";
    for (const auto& kv : tagNames)
      out << "<map key=\"" << kv.second << "\" dim=\"" << (kv.first >= 1000 || kv.first == 0 ? 2 : 3) << "\">"
          << kv.first << "</map>";
    out << "</main>]]></Information>\n";
    out << "      <Topology TopologyType=\"" << topologyType << "\" NumberOfElements=\"" << count
        << "\" NodesPerElement=\"" << per << "\">\n        <DataItem Dimensions=\"" << count << " " << per
        << "\" NumberType=\"Int\" Format=\"XML\">\n";
  };
  auto geometry = [&](amTextOutput& out) {
    out << "        </DataItem>\n      </Topology>\n      <Geometry GeometryType=\"XYZ\">\n        <DataItem "
           "Dimensions=\""
        << used << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">\n";
    for (vtkIdType i = 0; i < np; ++i)
      if (number[i] >= 0)
        out << xyz[3 * i] << " " << xyz[3 * i + 1] << " " << xyz[3 * i + 2] << "\n";
    out << "        </DataItem>\n      </Geometry>\n";
  };
  auto attribute = [&](amTextOutput& out, const char* name, std::size_t count) {
    out << "      <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "        <DataItem Dimensions=\"" << count << "\" NumberType=\"Int\" Format=\"XML\">\n";
  };
  const char* tail = "        </DataItem>\n      </Attribute>\n    </Grid>\n  </Domain>\n</Xdmf>\n";
  {
    std::ofstream stream(meshFile.TemporaryPath());
    amTextOutput out(stream);
    head(out, "mesh", "Tetrahedron", static_cast<std::size_t>(nc), 4);
    for (const auto& t : tets)
      out << number[t[0]] << " " << number[t[1]] << " " << number[t[2]] << " " << number[t[3]] << "\n";
    geometry(out);
    attribute(out, "cell_tags", static_cast<std::size_t>(nc));
    for (int l : labels)
      out << l << "\n";
    // The fibres and sheets where the mesh has them (Ventricular Fibres), after the tags: FEniCSx's
    // read_meshtags takes a grid's first attribute.
    for (const char* name : { "Fibers", "Sheets" })
    {
      vtkDataArray* vectors = grid->GetCellData()->GetArray(name);
      if (!vectors || vectors->GetNumberOfComponents() != 3)
        continue;
      out << "        </DataItem>\n      </Attribute>\n      <Attribute Name=\"" << name
          << "\" AttributeType=\"Vector\" Center=\"Cell\">\n        <DataItem Dimensions=\"" << nc
          << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">\n";
      double v[3];
      for (vtkIdType c = 0; c < nc; ++c)
      {
        vectors->GetTuple(c, v);
        out << v[0] << " " << v[1] << " " << v[2] << "\n";
      }
    }
    out << tail;
    if (!out.Flush())
    {
      vtkErrorMacro("Cannot write '" << target << "': output error (disk full?).");
      return 0;
    }
  }
  this->UpdateProgress(0.6);
  {
    std::ofstream stream(facetsFile.TemporaryPath());
    amTextOutput out(stream);
    head(out, "facet_tags", "Triangle", faces.size(), 3);
    for (const auto& f : faces)
      out << number[f.Points[0]] << " " << number[f.Points[1]] << " " << number[f.Points[2]] << "\n";
    geometry(out);
    attribute(out, "facet_tags", faces.size());
    for (const auto& f : faces)
      out << 1000LL * f.First + (f.Second == amTetraFaces::Outside() ? 0 : f.Second) << "\n";
    out << tail;
    if (!out.Flush())
    {
      vtkErrorMacro("Cannot write '" << facetsTarget << "': output error (disk full?).");
      return 0;
    }
  }
  if (!meshFile.Commit(why) || !facetsFile.Commit(why))
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
}
