// Small hand-made meshes shared by the mesh writers' and readers' tests.
#ifndef amTestMeshes_h
#define amTestMeshes_h

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <vector>

namespace amTest
{
/// Two tetrahedra 'a' and 'b' on 'points' (double precision; a point neither uses may be among them), with
/// cell data "Region" holding 'regionA' and 'regionB'.
inline vtkSmartPointer<vtkUnstructuredGrid> TwoTetrahedra(const std::vector<std::array<double, 3>>& points,
  const std::array<vtkIdType, 4>& a, const std::array<vtkIdType, 4>& b, int regionA, int regionB)
{
  auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  for (const auto& q : points)
    p->InsertNextPoint(q.data());
  g->SetPoints(p);
  g->InsertNextCell(VTK_TETRA, 4, a.data());
  g->InsertNextCell(VTK_TETRA, 4, b.data());
  vtkNew<vtkIntArray> r;
  r->SetName("Region");
  r->InsertNextValue(regionA);
  r->InsertNextValue(regionB);
  g->GetCellData()->AddArray(r);
  return g;
}
}

#endif
