// A structured tetrahedral box mesh for the tests and benchmarks (header only, VTK common only).
#ifndef amBoxMesh_h
#define amBoxMesh_h

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <functional>
#include <utility>

namespace amTest
{
/// A box [origin, origin + size] cut into n[0] x n[1] x n[2] cubes of 6 tetrahedra each (Kuhn's
/// subdivision along the main diagonal, conforming between cubes). Cell data "Region" from
/// region(centroid) (all 1 when null).
inline vtkSmartPointer<vtkUnstructuredGrid> BoxMesh(const int n[3], const double origin[3], const double size[3],
  const std::function<int(const double*)>& region = nullptr)
{
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto id = [&](int i, int j, int k) { return static_cast<vtkIdType>((k * (n[1] + 1) + j) * (n[0] + 1) + i); };
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i)
        points->InsertNextPoint(
          origin[0] + size[0] * i / n[0], origin[1] + size[1] * j / n[1], origin[2] + size[2] * k / n[2]);
  mesh->SetPoints(points);
  vtkNew<vtkIntArray> regions;
  regions->SetName("Region");
  static const int perm[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  mesh->Allocate(6 * n[0] * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        for (const auto& p : perm)
        {
          int c[3] = { i, j, k };
          vtkIdType ids[4];
          ids[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++c[p[s]];
            ids[s + 1] = id(c[0], c[1], c[2]);
          }
          double centroid[3] = { 0, 0, 0 };
          for (vtkIdType v : ids)
          {
            double x[3];
            points->GetPoint(v, x);
            for (int d = 0; d < 3; ++d)
              centroid[d] += 0.25 * x[d];
          }
          // Positive orientation for VTK (the Kuhn tetrahedra alternate in sign).
          double a[3], b[3], e[3], x0[3], x1[3], x2[3], x3[3];
          points->GetPoint(ids[0], x0);
          points->GetPoint(ids[1], x1);
          points->GetPoint(ids[2], x2);
          points->GetPoint(ids[3], x3);
          for (int d = 0; d < 3; ++d)
          {
            a[d] = x1[d] - x0[d];
            b[d] = x2[d] - x0[d];
            e[d] = x3[d] - x0[d];
          }
          const double det = a[0] * (b[1] * e[2] - b[2] * e[1]) - a[1] * (b[0] * e[2] - b[2] * e[0]) +
            a[2] * (b[0] * e[1] - b[1] * e[0]);
          if (det < 0)
            std::swap(ids[2], ids[3]);
          mesh->InsertNextCell(VTK_TETRA, 4, ids);
          regions->InsertNextValue(region ? region(centroid) : 1);
        }
  mesh->GetCellData()->AddArray(regions);
  return mesh;
}
}

#endif
