#include "amMeshQuality.h"

#include "amQualityTable.h"
#include "amUnits.h"

#include "amTetraGeometry.h"

#include "amThreading.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

vtkStandardNewMacro(amMeshQuality);

namespace
{
using Vec = amTetraGeometry::Vec;
constexpr auto Cross = &amTetraGeometry::Cross;
constexpr auto Dot = &amTetraGeometry::Dot;
constexpr auto Norm = &amTetraGeometry::Norm;
constexpr auto Sub = &amTetraGeometry::Sub;
}

void amMeshQuality::TetraQuality(const double p0[3], const double p1[3], const double p2[3], const double p3[3],
  double& quality, double& minDihedral, double& maxDihedral, double& radiusRatio, double& volume)
{
  const double* p[4] = { p0, p1, p2, p3 };
  volume = amTetraGeometry::SignedVolume(p0, p1, p2, p3);
  // Outward-facing (for positive volume) face normals, face i opposite vertex i.
  static const int faceOf[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
  Vec n[4];
  double area = 0;
  for (int f = 0; f < 4; ++f)
  {
    n[f] = Cross(Sub(p[faceOf[f][1]], p[faceOf[f][0]]), Sub(p[faceOf[f][2]], p[faceOf[f][0]]));
    area += 0.5 * Norm(n[f]);
  }
  double longest = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest = std::max(longest, Norm(Sub(p[j], p[i])));
  const double inradius = area > 0 ? 3.0 * std::fabs(volume) / area : 0.0;
  const double inf = std::numeric_limits<double>::infinity();
  quality = inradius > 0 ? std::sqrt(6.0) / 12.0 * longest / inradius : inf;
  // Dihedral angle at the edge shared by faces f and g: pi - angle between their outward normals.
  minDihedral = 180.0;
  maxDihedral = 0.0;
  for (int f = 0; f < 4; ++f)
    for (int g = f + 1; g < 4; ++g)
    {
      const double nf = Norm(n[f]), ng = Norm(n[g]);
      double angle = 0.0;
      if (nf > 0 && ng > 0)
      {
        const double cosine = std::max(-1.0, std::min(1.0, Dot(n[f], n[g]) / (nf * ng)));
        angle = 180.0 - std::acos(cosine) * 180.0 / M_PI;
      }
      if (volume <= 0)
        angle = 0.0;
      minDihedral = std::min(minDihedral, angle);
      maxDihedral = std::max(maxDihedral, volume <= 0 ? 180.0 : angle);
    }
  const double circumradius = amTetraGeometry::Circumradius(p0, p1, p2, p3);
  radiusRatio = inradius > 0 ? circumradius / (3.0 * inradius) : inf;
}

amMeshQuality::amMeshQuality()
  : RegionArrayName(nullptr)
  , MeanQuality(0)
  , MaximumQuality(0)
  , MinimumDihedralAngle(0)
  , MaximumDihedralAngle(0)
  , NumberOfInvertedTetrahedra(0)
{
  amThreading::Initialize();
  this->SetRegionArrayName("Region");
  this->SetNumberOfOutputPorts(2);
}

amMeshQuality::~amMeshQuality()
{
  this->SetRegionArrayName(nullptr);
}

int amMeshQuality::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkTable");
  return 1;
}

int amMeshQuality::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkTable* table = vtkTable::GetData(outputVector, 1);
  if (input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input mesh has no cells.");
    return 0;
  }
  // A mesh read back from Medit or Gmsh carries its boundary triangles (and maybe edges) beside
  // its tetrahedra: the tetrahedra are measured, the other cells left out of the output.
  vtkNew<vtkUnstructuredGrid> tetrahedraOnly;
  if (!amMeshQuality::TetrahedraOf(input, tetrahedraOnly))
  {
    vtkErrorMacro("The input mesh has no tetrahedron (its " << input->GetNumberOfCells() << " cells are of VTK type "
                                                            << input->GetCellType(0)
                                                            << "...); MeshQuality measures tetrahedral meshes.");
    return 0;
  }
  if (tetrahedraOnly->GetNumberOfCells() > 0)
    input = tetrahedraOnly;
  const vtkIdType ne = input->GetNumberOfCells();
  vtkDataArray* regionArray =
    this->RegionArrayName && *this->RegionArrayName ? input->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  vtkPoints* pts = input->GetPoints();
  for (vtkIdType v = 0; v < input->GetNumberOfPoints(); ++v)
  {
    double x[3];
    pts->GetPoint(v, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      vtkErrorMacro("Point " << v << " has a non-finite coordinate.");
      return 0;
    }
  }
  vtkCellArray* cells = input->GetCells();
  std::vector<std::array<vtkIdType, 4>> tets(static_cast<size_t>(ne));
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    vtkIdType c = 0;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++c)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      std::copy(ids, ids + 4, tets[c].begin());
      for (int k = 0; k < 4; ++k)
        if (ids[k] < 0 || ids[k] >= input->GetNumberOfPoints())
        {
          vtkErrorMacro("Tetrahedron " << c << " refers to point " << ids[k] << ", but the mesh has "
                                       << input->GetNumberOfPoints() << " points.");
          return 0;
        }
    }
  }
  std::vector<int> region(static_cast<size_t>(ne), 0);
  if (regionArray)
    for (vtkIdType c = 0; c < ne; ++c)
      region[c] = static_cast<int>(regionArray->GetComponent(c, 0));

  vtkNew<vtkDoubleArray> q, dmin, dmax, rr, vol;
  q->SetName("Quality");
  dmin->SetName("MinimumDihedralAngle");
  dmax->SetName("MaximumDihedralAngle");
  rr->SetName("RadiusRatio");
  vol->SetName("Volume");
  for (auto* a : { q.Get(), dmin.Get(), dmax.Get(), rr.Get(), vol.Get() })
    a->SetNumberOfTuples(ne);
  vtkSMPTools::For(0, ne, [&](vtkIdType c0, vtkIdType c1) {
    double x[4][3];
    for (vtkIdType c = c0; c < c1; ++c)
    {
      for (int i = 0; i < 4; ++i)
        pts->GetPoint(tets[c][i], x[i]);
      double qq, a, b, r, v;
      amMeshQuality::TetraQuality(x[0], x[1], x[2], x[3], qq, a, b, r, v);
      q->SetValue(c, qq);
      dmin->SetValue(c, a);
      dmax->SetValue(c, b);
      rr->SetValue(c, r);
      vol->SetValue(c, v);
    }
  });
  this->UpdateProgress(0.5);

  std::map<int, amQualityTable::Row> rows;
  amQualityTable::Row all;
  amQualityTable::Count(tets, region, input->GetNumberOfPoints(), q->GetPointer(0), dmin->GetPointer(0),
    dmax->GetPointer(0), vol->GetPointer(0), rows, all);

  const char* names[] = { "Region", "np", "nt", "ne", "MeanQuality", "MinimumQuality", "MaximumQuality",
    "MinimumDihedralAngle", "MaximumDihedralAngle", "Volume", "InvertedTetrahedra" };
  std::vector<vtkSmartPointer<vtkAbstractArray>> columns;
  for (int i = 0; i < 11; ++i)
  {
    vtkSmartPointer<vtkDataArray> a;
    if (i < 4 || i == 10)
      a = vtkSmartPointer<vtkIdTypeArray>::New();
    else
      a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(names[i]);
    if (i == 7 || i == 8)
      amUnits::Set(a, "deg");
    if (i == 9)
      amUnits::Set(a, "mm3");
    columns.push_back(a);
    table->AddColumn(a);
  }
  auto addRow = [&](int label, const amQualityTable::Row& r) {
    const double values[11] = { static_cast<double>(label), static_cast<double>(r.np), static_cast<double>(r.nt),
      static_cast<double>(r.ne), r.ne ? r.sumQ / r.ne : 0.0, r.minQ, r.maxQ, r.minD, r.maxD, r.volume,
      static_cast<double>(r.inverted) };
    for (int i = 0; i < 11; ++i)
      vtkDataArray::SafeDownCast(columns[i])->InsertNextTuple1(values[i]);
  };
  for (const auto& kv : rows)
    addRow(kv.first, kv.second);
  addRow(-1, all);

  this->MeanQuality = all.sumQ / static_cast<double>(all.ne);
  this->MaximumQuality = all.maxQ;
  this->MinimumDihedralAngle = all.minD;
  this->MaximumDihedralAngle = all.maxD;
  this->NumberOfInvertedTetrahedra = all.inverted;

  output->ShallowCopy(input);
  for (auto* a : { q.Get(), dmin.Get(), dmax.Get(), rr.Get(), vol.Get() })
    output->GetCellData()->AddArray(a);
  this->UpdateProgress(1.0);
  return 1;
}

bool amMeshQuality::TetrahedraOf(vtkUnstructuredGrid* grid, vtkUnstructuredGrid* tetrahedra)
{
  const vtkIdType n = grid->GetNumberOfCells();
  vtkIdType count = 0;
  for (vtkIdType c = 0; c < n; ++c)
    count += grid->GetCellType(c) == VTK_TETRA ? 1 : 0;
  if (count == 0)
    return false;
  if (count == n)
    return true;
  tetrahedra->SetPoints(grid->GetPoints());
  tetrahedra->GetPointData()->ShallowCopy(grid->GetPointData());
  tetrahedra->GetFieldData()->ShallowCopy(grid->GetFieldData());
  tetrahedra->GetCellData()->CopyAllocate(grid->GetCellData(), count);
  tetrahedra->AllocateExact(count, 4 * count);
  for (vtkIdType c = 0; c < n; ++c)
    if (grid->GetCellType(c) == VTK_TETRA)
    {
      vtkIdType np;
      const vtkIdType* ids;
      grid->GetCellPoints(c, np, ids);
      const vtkIdType id = tetrahedra->InsertNextCell(VTK_TETRA, 4, ids);
      tetrahedra->GetCellData()->CopyData(grid->GetCellData(), c, id);
    }
  return true;
}

void amMeshQuality::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)") << "\n";
}
