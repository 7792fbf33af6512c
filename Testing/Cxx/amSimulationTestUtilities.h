// Structured tetrahedral meshes for the simulation tests and benchmarks.
#ifndef amSimulationTestUtilities_h
#define amSimulationTestUtilities_h

#include "amBoxMesh.h"
#include "amFitzHughNagumoSolver.h"
#include "amP1Assembly.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <functional>
#include <set>

namespace amTest
{
/// The tetrahedra of a grid as a finite-element mesh (points and cells in the grid's order).
inline amP1Assembly FemOf(vtkUnstructuredGrid* mesh)
{
  amP1Assembly fem;
  fem.Points.resize(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    mesh->GetPoint(i, fem.Points[i].data());
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids;
    vtkIdType npts;
    mesh->GetCellPoints(c, npts, ids);
    fem.Tetrahedra.push_back({ ids[0], ids[1], ids[2], ids[3] });
  }
  return fem;
}

/// The slab of the Niederer et al. 2011 N-version benchmark, 20 x 7 x 3 mm at spacing dx, fibers
/// along x (cell data "Fibers"), on a solver set up as the tests and the benchmark run it:
/// transverse conductivity ratio 0.019/0.17 as in the benchmark, a 2.5 mm corner stimulus (2/ms for
/// 4 ms), the given time step, simulated up to endTime with one frame at the end.
inline vtkSmartPointer<vtkUnstructuredGrid> NiedererSlab(
  double dx, amFitzHughNagumoSolver* solver, double dt, double endTime)
{
  const int n[3] = { static_cast<int>(std::lround(20 / dx)), static_cast<int>(std::lround(7 / dx)),
    static_cast<int>(std::lround(3 / dx)) };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 20, 7, 3 };
  auto mesh = BoxMesh(n, origin, size);
  vtkNew<vtkDoubleArray> fibers;
  fibers->SetName("Fibers");
  fibers->SetNumberOfComponents(3);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    fibers->InsertNextTuple3(1, 0, 0);
  mesh->GetCellData()->AddArray(fibers);
  solver->SetInputData(mesh);
  solver->RemoveAllHeartRegions();
  solver->AddHeartRegion(1);
  solver->SetTransverseConductivityRatio(0.019 / 0.17);
  solver->SetTimeStep(dt);
  solver->SetEndTime(endTime);
  solver->SetOutputInterval(endTime);
  solver->SetStimulusCenter(0, 0, 0);
  solver->SetStimulusRadius(2.5);
  solver->SetStimulusStrength(2.0);
  solver->SetStimulusDuration(4.0);
  return mesh;
}

/// The heart (region 5) of 'mesh' as a heart solution: its nodes with InputPointId, "u" = f(x) and
/// "Vm" = 100 f(x) (mV), its region label on one cell (the heart solvers' outputs carry the same).
inline vtkSmartPointer<vtkUnstructuredGrid> StaticHeart(vtkUnstructuredGrid* mesh, double (*f)(const double*))
{
  auto heart = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkDataArray* regions = mesh->GetCellData()->GetArray("Region");
  std::set<vtkIdType> nodes;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    if (regions->GetComponent(c, 0) == 5)
    {
      const vtkIdType* ids;
      vtkIdType npts;
      mesh->GetCellPoints(c, npts, ids);
      nodes.insert(ids, ids + 4);
    }
  vtkNew<vtkPoints> points;
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("InputPointId");
  vtkNew<vtkDoubleArray> u, vm;
  u->SetName("u");
  vm->SetName("Vm");
  for (vtkIdType p : nodes)
  {
    double x[3];
    mesh->GetPoint(p, x);
    points->InsertNextPoint(x);
    ids->InsertNextValue(p);
    u->InsertNextValue(f(x));
    vm->InsertNextValue(100.0 * f(x));
  }
  heart->SetPoints(points);
  heart->GetPointData()->AddArray(ids);
  heart->GetPointData()->AddArray(u);
  heart->GetPointData()->AddArray(vm);
  vtkNew<vtkIntArray> r;
  r->SetName("Region");
  r->InsertNextValue(5);
  heart->GetCellData()->AddArray(r); // the heart's regions are read from its cells' labels
  heart->Allocate(1);
  vtkIdType cell[4] = { 0, 1, 2, 3 };
  heart->InsertNextCell(VTK_TETRA, 4, cell);
  return heart;
}

}

#endif
