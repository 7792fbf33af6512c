// Helpers of the surface suites: label maps from functions, the topology table as rows.
#ifndef amSurfaceTestUtilities_h
#define amSurfaceTestUtilities_h

#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include <algorithm>
#include <functional>
#include <map>
#include <string>

namespace amTest
{
/// An n0 x n1 x n2 int label map, voxel (i,j,k) at origin + spacing * (i,j,k), labels from f(x,y,z).
inline vtkSmartPointer<vtkImageData> LabelMap(
  int n0, int n1, int n2, double spacing, const double origin[3], const std::function<int(double, double, double)>& f)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(n0, n1, n2);
  img->SetSpacing(spacing, spacing, spacing);
  img->SetOrigin(origin[0], origin[1], origin[2]);
  img->AllocateScalars(VTK_INT, 1);
  auto* a = vtkIntArray::SafeDownCast(img->GetPointData()->GetScalars());
  a->SetName("Labels");
  for (int k = 0; k < n2; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i)
        a->SetValue((static_cast<vtkIdType>(k) * n1 + j) * n0 + i,
          f(origin[0] + spacing * i, origin[1] + spacing * j, origin[2] + spacing * k));
  return img;
}

/// Fraction of the triangles whose smallest angle is at least 'degrees'.
inline double AngleFraction(vtkPolyData* pd, double degrees)
{
  vtkIdType good = 0, npts;
  const vtkIdType* ids;
  for (pd->GetPolys()->InitTraversal(); pd->GetPolys()->GetNextCell(npts, ids);)
  {
    double p[3][3], smallest = 180;
    for (int k = 0; k < 3; ++k)
      pd->GetPoint(ids[k], p[k]);
    for (int k = 0; k < 3; ++k)
    {
      double u[3], v[3];
      vtkMath::Subtract(p[(k + 1) % 3], p[k], u);
      vtkMath::Subtract(p[(k + 2) % 3], p[k], v);
      smallest = std::min(smallest, vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(u, v)));
    }
    good += smallest >= degrees;
  }
  return static_cast<double>(good) / std::max<vtkIdType>(1, pd->GetNumberOfCells());
}

/// The topology table of amLabelSurface as label -> column name -> value.
inline std::map<int, std::map<std::string, double>> Rows(vtkTable* t)
{
  std::map<int, std::map<std::string, double>> rows;
  for (vtkIdType r = 0; r < t->GetNumberOfRows(); ++r)
  {
    const int label = t->GetValueByName(r, "Label").ToInt();
    for (vtkIdType c = 0; c < t->GetNumberOfColumns(); ++c)
      rows[label][t->GetColumnName(c)] = t->GetValue(r, c).ToDouble();
  }
  return rows;
}
}

#endif
