#include "amUnusedPoints.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <vector>

namespace
{
// The cells of 'cells' with every point id mapped through 'number'.
vtkSmartPointer<vtkCellArray> Renumbered(vtkCellArray* cells, const std::vector<vtkIdType>& number)
{
  auto out = vtkSmartPointer<vtkCellArray>::New();
  out->AllocateExact(cells->GetNumberOfCells(), cells->GetNumberOfConnectivityIds());
  vtkNew<vtkIdList> ids;
  const auto iter = vtk::TakeSmartPointer(cells->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    iter->GetCurrentCell(ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      ids->SetId(k, number[ids->GetId(k)]);
    out->InsertNextCell(ids);
  }
  return out;
}
}

vtkIdType amUnusedPoints::Remove(vtkUnstructuredGrid* mesh, vtkPolyData* surface)
{
  vtkPoints* points = mesh->GetPoints();
  const vtkIdType np = mesh->GetNumberOfPoints();
  if (!points || np == 0)
    return 0;
  std::vector<vtkIdType> number(np, -1);
  vtkCellArray* cells = mesh->GetCells();
  {
    vtkNew<vtkIdList> ids;
    const auto iter = vtk::TakeSmartPointer(cells->NewIterator());
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      iter->GetCurrentCell(ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        number[ids->GetId(k)] = 0;
    }
  }
  vtkIdType used = 0;
  for (vtkIdType& n : number)
    if (n == 0)
      n = used++;
  if (used == np)
    return 0;
  vtkNew<vtkPoints> kept;
  kept->SetDataType(points->GetDataType());
  kept->SetNumberOfPoints(used);
  vtkPointData* data = mesh->GetPointData();
  vtkNew<vtkPointData> keptData;
  keptData->CopyAllocate(data, used);
  for (vtkIdType i = 0; i < np; ++i)
    if (number[i] >= 0)
    {
      kept->SetPoint(number[i], points->GetPoint(i));
      keptData->CopyData(data, i, number[i]);
    }
  // The surface shares the mesh's points (or their numbering): it follows them.
  const bool follow = surface && (surface->GetPoints() == points || surface->GetNumberOfPoints() == np);
  vtkSmartPointer<vtkUnsignedCharArray> types = mesh->GetCellTypesArray();
  vtkSmartPointer<vtkCellArray> renumbered = Renumbered(cells, number);
  if (follow)
  {
    vtkPointData* surfaceData = surface->GetPointData();
    vtkNew<vtkPointData> keptSurfaceData;
    keptSurfaceData->CopyAllocate(surfaceData, used);
    for (vtkIdType i = 0; i < np; ++i)
      if (number[i] >= 0)
        keptSurfaceData->CopyData(surfaceData, i, number[i]);
    surface->SetPoints(kept);
    if (surface->GetPolys() && surface->GetPolys()->GetNumberOfCells() > 0)
      surface->SetPolys(Renumbered(surface->GetPolys(), number));
    surface->GetPointData()->ShallowCopy(keptSurfaceData);
  }
  mesh->SetPoints(kept);
  mesh->SetCells(types, renumbered);
  mesh->GetPointData()->ShallowCopy(keptData);
  return np - used;
}
