#include "amTetraSubset.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <set>
#include <sstream>

std::string amTetraSubset::SelectRegions(vtkUnstructuredGrid* input, vtkDataArray* regions, const char* regionArrayName,
  const std::vector<int>& wanted, std::vector<vtkIdType>& cells)
{
  cells.clear();
  const std::set<int> wantedSet(wanted.begin(), wanted.end());
  std::set<int> present;
  const vtkIdType nCells = input->GetNumberOfCells();
  for (vtkIdType c = 0; c < nCells; ++c)
  {
    if (regions)
    {
      const int label = static_cast<int>(regions->GetComponent(c, 0));
      present.insert(label);
      if (!wantedSet.count(label))
        continue;
    }
    if (input->GetCellType(c) != VTK_TETRA)
      return "cell " + std::to_string(c) + " of the heart is not a tetrahedron (VTK cell type " +
        std::to_string(input->GetCellType(c)) + "); the solver needs a tetrahedral mesh";
    cells.push_back(c);
  }
  if (!cells.empty())
    return "";
  std::ostringstream msg;
  msg << "no heart: no tetrahedron has a '" << (regionArrayName ? regionArrayName : "")
      << "' label among the heart regions (";
  for (int l : wanted)
    msg << " " << l;
  msg << " ); the mesh has regions (";
  for (int l : present)
    msg << " " << l;
  msg << " )" << (nCells == 0 ? " and no cells at all" : "");
  return msg.str();
}

std::vector<vtkIdType> amTetraSubset::NodesWithin(const double centre[3], double radius) const
{
  std::vector<vtkIdType> nodes;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(this->Fem.Points.size()); ++i)
  {
    double d2 = 0;
    for (int c = 0; c < 3; ++c)
      d2 += (this->Fem.Points[i][c] - centre[c]) * (this->Fem.Points[i][c] - centre[c]);
    if (d2 <= radius * radius)
      nodes.push_back(i);
  }
  return nodes;
}

void amTetraSubset::Build(vtkUnstructuredGrid* input, const std::vector<vtkIdType>& cells)
{
  this->Cells = cells;
  const vtkIdType nInput = input->GetNumberOfPoints();
  this->Local.assign(nInput, -1);
  for (vtkIdType c : cells)
  {
    const vtkIdType* pts;
    vtkIdType npts;
    input->GetCellPoints(c, npts, pts);
    for (int a = 0; a < 4; ++a)
      this->Local[pts[a]] = 0;
  }
  this->Global.clear();
  for (vtkIdType p = 0; p < nInput; ++p)
    if (this->Local[p] == 0)
    {
      this->Local[p] = static_cast<vtkIdType>(this->Global.size());
      this->Global.push_back(p);
    }
  const vtkIdType n = static_cast<vtkIdType>(this->Global.size());
  this->Fem.Points.resize(n);
  for (vtkIdType i = 0; i < n; ++i)
    input->GetPoint(this->Global[i], this->Fem.Points[i].data());
  this->Fem.Tetrahedra.resize(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k)
  {
    const vtkIdType* pts;
    vtkIdType npts;
    input->GetCellPoints(cells[k], npts, pts);
    for (int a = 0; a < 4; ++a)
      this->Fem.Tetrahedra[k][a] = this->Local[pts[a]];
  }
}

vtkSmartPointer<vtkUnstructuredGrid> amTetraSubset::MakeGrid(vtkDataArray* regions) const
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  const vtkIdType n = static_cast<vtkIdType>(this->Global.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
    points->SetPoint(i, this->Fem.Points[i].data());
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(this->Cells.size()));
  for (const auto& t : this->Fem.Tetrahedra)
    grid->InsertNextCell(VTK_TETRA, 4, t.data());
  if (regions)
  {
    vtkSmartPointer<vtkDataArray> r = vtk::TakeSmartPointer(regions->NewInstance());
    r->SetName(regions->GetName());
    r->SetNumberOfTuples(static_cast<vtkIdType>(this->Cells.size()));
    for (std::size_t k = 0; k < this->Cells.size(); ++k)
      r->SetComponent(static_cast<vtkIdType>(k), 0, regions->GetComponent(this->Cells[k], 0));
    grid->GetCellData()->AddArray(r);
  }
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("InputPointId");
  ids->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
    ids->SetValue(i, this->Global[i]);
  grid->GetPointData()->AddArray(ids);
  return grid;
}
