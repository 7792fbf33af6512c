#include "amTetGenOutput.h"

#include "amSurfaceMesh.h"
#include "amTetraGeometry.h"
#include "amTetraRegions.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace
{
using Vec = amTetraGeometry::Vec;
constexpr auto Cross = &amTetraGeometry::Cross;
constexpr auto Dot = &amTetraGeometry::Dot;
constexpr auto Sub = &amTetraGeometry::Sub;
}

bool amTetGenOutput::Build(const amSurfaceMesh& mesh, const amTetGenRun::Result& out, const amTetraRegions& regions,
  int bg, vtkUnstructuredGrid* grid, vtkPolyData* interfaces, std::string& why)
{
  const vtkIdType np = mesh.NumberOfPoints();
  const vtkIdType nOutPoints = out.NumberOfPoints, nTets = out.NumberOfTetrahedra, nSub = out.NumberOfFaces;
  const int* tets = out.Tetrahedra.data();
  const double* P = out.Points.data();
  std::vector<vtkIdType> newTet(static_cast<size_t>(nTets), -1);
  std::vector<vtkIdType> newPoint(static_cast<size_t>(nOutPoints), -1);
  vtkIdType kept = 0;
  for (vtkIdType t = 0; t < nTets; ++t)
    if (regions.Label[t] != bg)
    {
      newTet[t] = kept++;
      for (int i = 0; i < 4; ++i)
        newPoint[tets[4 * t + i]] = 0;
    }
  if (kept == 0)
  {
    why = "No tetrahedron lies in a region other than the background " + std::to_string(bg) + ".";
    return false;
  }
  // Input surface points first, in order; then the Steiner points that are used.
  vtkIdType nPoints = 0;
  for (vtkIdType v = 0; v < std::min(np, nOutPoints); ++v)
    newPoint[v] = nPoints++;
  for (vtkIdType v = np; v < nOutPoints; ++v)
    if (newPoint[v] == 0)
      newPoint[v] = nPoints++;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nPoints);
  vtkNew<vtkIdTypeArray> surfaceId;
  surfaceId->SetName("SurfacePointId");
  surfaceId->SetNumberOfTuples(nPoints);
  for (vtkIdType v = 0; v < nOutPoints; ++v)
    if (newPoint[v] >= 0)
    {
      points->SetPoint(newPoint[v], P + 3 * v);
      surfaceId->SetValue(newPoint[v], v < np ? v : -1);
    }
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(kept + 1);
  connectivity->SetNumberOfTuples(4 * kept);
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  region->SetNumberOfTuples(kept);
  for (vtkIdType t = 0; t < nTets; ++t)
  {
    const vtkIdType o = newTet[t];
    if (o < 0)
      continue;
    vtkIdType ids[4];
    for (int i = 0; i < 4; ++i)
      ids[i] = newPoint[tets[4 * t + i]];
    if (amTetraGeometry::SignedVolume(
          P + 3 * tets[4 * t], P + 3 * tets[4 * t + 1], P + 3 * tets[4 * t + 2], P + 3 * tets[4 * t + 3]) < 0)
      std::swap(ids[0], ids[1]);
    offsets->SetValue(o, 4 * o);
    for (int i = 0; i < 4; ++i)
      connectivity->SetValue(4 * o + i, ids[i]);
    region->SetValue(o, regions.Label[t]);
  }
  offsets->SetValue(kept, 4 * kept);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetPoints(points);
  grid->SetCells(VTK_TETRA, cells);
  grid->GetCellData()->AddArray(region);
  grid->GetCellData()->SetActiveScalars("Region");
  grid->GetPointData()->AddArray(surfaceId);

  vtkNew<vtkCellArray> faces;
  faces->AllocateExact(nSub, 3 * nSub);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfComponents(2);
  labels->SetNumberOfTuples(nSub);
  vtkNew<vtkIdTypeArray> source, adjacent;
  source->SetName("SourceTriangle");
  source->SetNumberOfTuples(nSub);
  adjacent->SetName("Tetra");
  adjacent->SetNumberOfComponents(2);
  adjacent->SetNumberOfTuples(nSub);
  for (vtkIdType s = 0; s < nSub; ++s)
  {
    const vtkIdType src = amTetraRegions::SourceOf(out, s);
    vtkIdType ids[3] = { out.Faces[3 * s], out.Faces[3 * s + 1], out.Faces[3 * s + 2] };
    const auto& tri = mesh.Triangles[src];
    const Vec n0 = Cross(Sub(mesh.Points[tri[1]].data(), mesh.Points[tri[0]].data()),
      Sub(mesh.Points[tri[2]].data(), mesh.Points[tri[0]].data()));
    const Vec n1 = Cross(Sub(P + 3 * ids[1], P + 3 * ids[0]), Sub(P + 3 * ids[2], P + 3 * ids[0]));
    if (Dot(n0, n1) < 0)
      std::swap(ids[1], ids[2]);
    for (auto& id : ids)
      id = newPoint[id];
    faces->InsertNextCell(3, ids);
    labels->SetTypedTuple(s, mesh.Labels[src].data());
    source->SetValue(s, src);
    for (int k = 0; k < 2; ++k)
    {
      const vtkIdType t = regions.SubfaceTet[s][k];
      adjacent->SetComponent(s, k, t >= 0 ? static_cast<double>(newTet[t]) : -1.0);
    }
  }
  interfaces->SetPoints(points);
  interfaces->SetPolys(faces);
  interfaces->GetCellData()->AddArray(labels);
  interfaces->GetCellData()->AddArray(source);
  interfaces->GetCellData()->AddArray(adjacent);
  return true;
}
