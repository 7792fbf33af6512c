// Simulation benchmark: wall seconds per simulated millisecond and peak memory of the FitzHugh-
// Nagumo solver and the torso potentials on the phantom's tetrahedral mesh (CGAL backend from the
// exact labels), and the Niederer-style slab activation table at several dx and dt.
// Run: build/bin/BenchmarkSimulation [phantom|slab|all] [FACET_MM CELL_MM SPACING_MM END_MS DT_MS]
// (the torso is solved at every output millisecond: every step at dt = 1 ms, every 10th at 0.1 ms).
#include "amFitzHughNagumoSolver.h"
#include "amLabelMapTetrahedralize.h"
#include "amThoraxPhantomSource.h"
#include "amTorsoPotential.h"

#include "../Cxx/amSimulationTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/resource.h>

namespace
{
double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double PeakMB()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

void Phantom(double facet, double cell, double spacing, double endTime, double dt)
{
  auto start = std::chrono::steady_clock::now();
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(spacing, spacing, spacing);
  vtkNew<amLabelMapTetrahedralize> mesher;
  mesher->SetInputConnection(phantom->GetOutputPort(1));
  mesher->SetFacetSize(facet);
  mesher->SetCellSize(cell);
  mesher->SetFacetDistance(std::min(1.0, facet / 4));
  mesher->Update(0);
  vtkDataObject* mesh = mesher->GetOutputDataObject(0);
  const double meshSeconds = Seconds(start);
  vtkNew<amFitzHughNagumoSolver> heart;
  heart->SetInputConnection(mesher->GetOutputPort(0));
  heart->SetStimulusCenter(61, -51.5, -25);
  heart->SetTimeStep(dt);
  heart->SetEndTime(endTime);
  heart->SetOutputInterval(std::max(dt, 1.0)); // the torso at every millisecond
  vtkNew<amTorsoPotential> torso;
  torso->SetInputConnection(0, mesher->GetOutputPort(0));
  torso->SetInputConnection(1, heart->GetOutputPort());
  start = std::chrono::steady_clock::now();
  torso->Update();
  const double simSeconds = Seconds(start);
  std::printf("phantom %.1f mm labels, CGAL facet %.1f / cell %.1f mm: %lld points, %lld tetrahedra (meshing %.1f s)\n",
    spacing, facet, cell, static_cast<long long>(vtkDataSet::SafeDownCast(mesh)->GetNumberOfPoints()),
    static_cast<long long>(vtkDataSet::SafeDownCast(mesh)->GetNumberOfCells()), meshSeconds);
  std::printf("  heart: %lld nodes, %d steps of %.2f ms, %.1f CG iterations/step, %.2f s = %.4f s per simulated ms; "
              "activated %.1f %%\n",
    static_cast<long long>(heart->GetNumberOfHeartNodes()), heart->GetNumberOfSteps(), dt, heart->GetMeanIterations(),
    heart->GetWallSeconds(), heart->GetWallSeconds() / endTime, 100 * heart->GetActivatedFraction());
  if (torso->GetSolver() == amTorsoPotential::DIRECT)
    std::printf("  torso: %lld nodes, Cholesky factor %.1f M non-zeros in %.2f s, %d solves (every %.1f ms), %.2f s "
                "= %.4f s per simulated ms\n",
      static_cast<long long>(torso->GetNumberOfTorsoNodes()), torso->GetFactorNonZeros() / 1e6,
      torso->GetFactorSeconds(), torso->GetNumberOfSolves(), heart->GetOutputInterval(), torso->GetWallSeconds(),
      torso->GetWallSeconds() / endTime);
  else
    std::printf("  torso: %lld nodes, %d solves (every %.1f ms), %.1f CG iterations each, %.2f s = %.4f s per "
                "simulated ms\n",
      static_cast<long long>(torso->GetNumberOfTorsoNodes()), torso->GetNumberOfSolves(), heart->GetOutputInterval(),
      torso->GetMeanIterations(), torso->GetWallSeconds(), torso->GetWallSeconds() / endTime);
  std::printf("  heart + torso: %.1f s for %.0f ms (%.3f s per simulated ms); peak memory %.0f MB\n", simSeconds,
    endTime, simSeconds / endTime, PeakMB());
}

void Slab()
{
  std::printf(
    "Niederer-style slab 20 x 7 x 3 mm, fibers along x (conductivity 3.5 / 0.39 mm^2/ms), corner stimulus:\n");
  std::printf("  %6s %6s %10s %10s %10s %8s\n", "dx", "dt", "P1 ms", "centre ms", "P8 ms", "wall s");
  for (double dx : { 0.5, 0.25, 0.2 })
    for (double dt : { 0.1, 0.05, 0.01 })
    {
      vtkNew<amFitzHughNagumoSolver> solver;
      amTest::NiedererSlab(dx, solver, dt, 110);
      solver->Update();
      vtkUnstructuredGrid* out = solver->GetOutput();
      vtkDataArray* act = out->GetPointData()->GetArray("ActivationTime");
      auto at = [&](double x, double y, double z) { return act->GetComponent(out->FindPoint(x, y, z), 0); };
      std::printf("  %6.2f %6.2f %10.2f %10.2f %10.2f %8.2f\n", dx, dt, at(0, 0, 0), at(10, 3.5, 1.5), at(20, 7, 3),
        solver->GetWallSeconds());
    }
}
}

int main(int argc, char* argv[])
{
  if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
    vtkSMPTools::SetBackend("STDThread");
  const std::string what = argc > 1 ? argv[1] : "all";
  if (what == "phantom" && argc > 6)
  {
    Phantom(std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5]), std::atof(argv[6]));
    return 0;
  }
  if (what == "slab" || what == "all")
    Slab();
  if (what == "phantom" || what == "all")
  {
    Phantom(4, 6, 2, 500, 1.0);       // the paper's 1 ms step
    Phantom(2.3, 3.1, 1.5, 500, 1.0); // the paper's scale: ~250 k vertices, ~1.5 M tetrahedra
    Phantom(2.3, 3.1, 1.5, 500, 0.1);
  }
  return 0;
}
