// Heartbeat benchmark: the wall seconds of fibres, activation and repolarisation, and the 12 leads
// over a 500 ms beat (VentricularFibres, ReactionEikonalSolver, LeadFieldECG sampled every 1 ms), and
// of the paper's model on the same mesh in the same run (FitzHugh-Nagumo at 0.5 ms, the torso
// potentials at every 5 ms frame), as a ratio.
// Run: build/bin/BenchmarkHeartbeat [MESH.vtu LANDMARKS.vtp] (the main job's thorax_tets.vtu and
// thorax_landmarks.vtp; without them: the phantom's exact labels at 1 mm meshed by CGAL, facet 4 mm).
// build/bin/BenchmarkHeartbeat slab [DX DT]: the N-version benchmark's slab (Niederer et al. 2011:
// 20 x 7 x 3 mm, fibres along x, sigma 0.17 / 0.019 S/m, chi 1400 /cm, Cm 1 uF/cm2, a 1.5 mm corner
// stimulus) with the Mitchell-Schaeffer monodomain at several dx and dt (or the one given): activation
// at the far corner P8 and the centre, a self-convergence study of the model we ship.
#include "../Cxx/amSimulationTestUtilities.h"
#include "amCardiacLandmarks.h"
#include "amFitzHughNagumoSolver.h"
#include "amLabelMapTetrahedralize.h"
#include "amLeadFieldECG.h"
#include "amMitchellSchaeffer.h"
#include "amMonodomainStepper.h"
#include "amReactionEikonalSolver.h"
#include "amThoraxPhantomSource.h"
#include "amTorsoPotential.h"
#include "amVentricularFibres.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}

// The slab at dx, stepped at dt: activation times at P8 (20, 7, 3) and the centre (10, 3.5, 1.5), ms.
void Slab(double dx, double dt)
{
  const auto start = std::chrono::steady_clock::now();
  const int n[3] = { static_cast<int>(std::lround(20 / dx)), static_cast<int>(std::lround(7 / dx)),
    static_cast<int>(std::lround(3 / dx)) };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 20, 7, 3 };
  const amP1Assembly fem = amTest::FemOf(amTest::BoxMesh(n, origin, size));
  // D = sigma / (chi Cm): 0.17 S/m / (1400 /cm x 1 uF/cm2) = 0.1214 mm2/ms, 0.019 S/m: 0.01357 mm2/ms.
  const double f[3] = { 1, 0, 0 };
  std::vector<std::array<double, 6>> tensors(
    fem.Tetrahedra.size(), amP1Assembly::FiberTensor(0.17 / 1.4, 0.019 / 1.4, f));
  std::vector<unsigned char> stimulated(fem.Points.size(), 0);
  for (std::size_t i = 0; i < fem.Points.size(); ++i)
    stimulated[i] = fem.Points[i][0] <= 1.5 + 1e-9 && fem.Points[i][1] <= 1.5 + 1e-9 && fem.Points[i][2] <= 1.5 + 1e-9;
  const amMitchellSchaeffer model;
  amMonodomainStepper mono;
  amMonodomainStepper::Parameters p;
  p.TimeStep = dt;
  p.StimulusDuration = 2;
  p.StimulusStrength = 100;
  if (!mono.Setup(fem, tensors, stimulated, model, p))
  {
    std::printf("  dx %.3f dt %.3f: %s\n", dx, dt, mono.Error.c_str());
    return;
  }
  auto node = [&](double x, double y, double z) {
    std::size_t best = 0;
    double bestD = 1e300;
    for (std::size_t i = 0; i < fem.Points.size(); ++i)
    {
      const double d =
        std::fabs(fem.Points[i][0] - x) + std::fabs(fem.Points[i][1] - y) + std::fabs(fem.Points[i][2] - z);
      if (d < bestD)
      {
        bestD = d;
        best = i;
      }
    }
    return best;
  };
  const std::size_t p8 = node(20, 7, 3), centre = node(10, 3.5, 1.5);
  const int steps = static_cast<int>(std::lround(200.0 / dt));
  for (int s = 0; s < steps && mono.Activation[p8] < 0; ++s)
    mono.Step(s * dt);
  std::printf("  dx %.3f mm, dt %.3f ms: %zu nodes; P8 %.2f ms, centre %.2f ms (%.1f s)\n", dx, dt, fem.Points.size(),
    mono.Activation[p8], mono.Activation[centre], Seconds(start));
}

int main(int argc, char* argv[])
{
  vtkSMPTools::SetBackend("STDThread");
  if (argc >= 2 && std::string(argv[1]) == "slab")
  {
    std::printf("N-version slab, Mitchell-Schaeffer monodomain (activation: Vm crossing -35 mV):\n");
    if (argc == 4) // one level: slab DX DT
    {
      Slab(std::atof(argv[2]), std::atof(argv[3]));
      return 0;
    }
    for (double dx : { 0.5, 0.25, 0.2 })
      for (double dt : { 0.05, 0.02, 0.01 })
        Slab(dx, dt);
    return 0;
  }
  vtkSmartPointer<vtkUnstructuredGrid> mesh;
  vtkSmartPointer<vtkPolyData> landmarks;
  if (argc >= 3)
  {
    vtkNew<vtkXMLUnstructuredGridReader> meshReader;
    meshReader->SetFileName(argv[1]);
    meshReader->Update();
    mesh = meshReader->GetOutput();
    vtkNew<vtkXMLPolyDataReader> landmarkReader;
    landmarkReader->SetFileName(argv[2]);
    landmarkReader->Update();
    landmarks = landmarkReader->GetOutput();
  }
  else
  {
    vtkNew<amThoraxPhantomSource> phantom;
    phantom->SetSpacing(1, 1, 1);
    vtkNew<amLabelMapTetrahedralize> mesher;
    mesher->SetInputConnection(phantom->GetOutputPort(1));
    mesher->SetFacetSize(4);
    mesher->SetCellSize(6);
    mesher->SetFacetDistance(1);
    mesher->Update(0);
    mesh = vtkUnstructuredGrid::SafeDownCast(mesher->GetOutputDataObject(0));
    vtkNew<amCardiacLandmarks> marks;
    marks->SetInputConnection(phantom->GetOutputPort(1));
    marks->Update();
    landmarks = marks->GetOutput();
  }
  std::printf("mesh: %lld points, %lld tetrahedra\n", static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(mesh->GetNumberOfCells()));

  auto start = std::chrono::steady_clock::now();
  vtkNew<amVentricularFibres> fibres;
  fibres->SetInputData(mesh);
  fibres->SetInputData(1, landmarks);
  fibres->Update();
  const double fibreSeconds = Seconds(start);
  vtkNew<amReactionEikonalSolver> heart;
  heart->SetInputConnection(fibres->GetOutputPort(0));
  heart->SetTagsConnection(fibres->GetOutputPort(1));
  vtkNew<amLeadFieldECG> ecg;
  ecg->SetInputConnection(0, fibres->GetOutputPort(0));
  ecg->SetHeartConnection(heart->GetOutputPort());
  ecg->SetInputData(2, landmarks);
  ecg->Update();
  const double beatSeconds = Seconds(start);
  std::printf("heartbeat: %.2f s in all (fibres %.2f s, activation and action potentials %.2f s, lead fields %.2f s, "
              "%d frames read); %lld heart nodes, activation %.1f-%.1f ms, QRS %.0f ms, QT %.0f ms\n",
    beatSeconds, fibreSeconds, heart->GetWallSeconds(), ecg->GetLeadFieldSeconds(), ecg->GetNumberOfFrames(),
    static_cast<long long>(heart->GetNumberOfHeartNodes()), heart->GetFirstActivation(), heart->GetLastActivation(),
    ecg->GetQRSDuration(), ecg->GetQTInterval());

  // The paper's model on the same mesh: FitzHugh-Nagumo, the heart's potential imposed on the torso.
  start = std::chrono::steady_clock::now();
  vtkNew<amFitzHughNagumoSolver> paper;
  paper->SetInputData(mesh);
  paper->SetInputData(1, landmarks);
  paper->SetStimulusRadius(15);
  paper->SetTimeStep(0.5);
  paper->SetEndTime(500);
  paper->SetOutputInterval(5);
  vtkNew<amTorsoPotential> torso;
  torso->SetInputData(0, mesh);
  torso->SetInputConnection(1, paper->GetOutputPort());
  torso->SetInputData(2, landmarks);
  torso->Update(1);
  const double paperSeconds = Seconds(start);
  std::printf("the paper's model (FitzHugh-Nagumo 0.5 ms steps, torso every 5 ms): %.2f s; heartbeat / paper %.2f\n",
    paperSeconds, beatSeconds / paperSeconds);
  return 0;
}
