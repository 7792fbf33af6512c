// Heartbeat benchmark: the wall seconds of fibres, activation and repolarisation, and the 12 leads
// over a 500 ms beat (VentricularFibres, ReactionEikonalSolver, LeadFieldECG sampled every 1 ms), and
// of the paper's model on the same mesh in the same run (FitzHugh-Nagumo at 0.5 ms, the torso
// potentials at every 5 ms frame), as a ratio.
// Run: build/bin/BenchmarkHeartbeat [MESH.vtu LANDMARKS.vtp] (the main job's thorax_tets.vtu and
// thorax_landmarks.vtp; without them: the phantom's exact labels at 1 mm meshed by CGAL, facet 4 mm).
#include "amCardiacLandmarks.h"
#include "amFitzHughNagumoSolver.h"
#include "amLabelMapTetrahedralize.h"
#include "amLeadFieldECG.h"
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
#include <cstdio>

namespace
{
double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}

int main(int argc, char* argv[])
{
  vtkSMPTools::SetBackend("STDThread");
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
