// FitzHugh-Nagumo (Rogers-McCulloch) monodomain solver: plane-wave speed against the bistable
// equation's analytic speed, convergence orders, a Niederer-style slab, time handling, bad input.
#include "amFitzHughNagumoSolver.h"
#include "amSimulationTestUtilities.h"
#include "amTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
// Mean activation time of the output nodes at coordinate x (axis 0).
double ActivationAt(vtkUnstructuredGrid* out, double x, double tol = 1e-6)
{
  vtkDataArray* act = out->GetPointData()->GetArray("ActivationTime");
  double sum = 0;
  int count = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    if (std::fabs(out->GetPoint(i)[0] - x) < tol)
    {
      sum += act->GetComponent(i, 0);
      ++count;
    }
  return count ? sum / count : -1;
}

// A cable-like slab 60 mm long, one element thick: a plane wave from x = 0 with the recovery
// variable frozen (c3 = 0) solves the bistable equation u_t = D u_xx + k u(u-a)(1-u), whose
// travelling front has the speed sqrt(kD/2)(1-2a). The speed is measured between x = 30 and 42 mm,
// where the front has settled after its launch and does not yet feel the far wall.
double PlaneWaveSpeed(double h, double dt)
{
  const int n[3] = { static_cast<int>(std::lround(60.0 / h)), 1, 1 };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 60.0, h, h };
  auto mesh = amTest::BoxMesh(n, origin, size);
  vtkNew<amFitzHughNagumoSolver> solver;
  solver->SetInputData(mesh);
  solver->RemoveAllHeartRegions();
  solver->AddHeartRegion(1);
  solver->SetConductivity(1.0);
  solver->SetC3(0.0);
  solver->SetTimeStep(dt);
  solver->SetEndTime(170.0);
  solver->SetOutputInterval(170.0);
  solver->SetStimulusCenter(0, 0, 0);
  solver->SetStimulusRadius(3.0);
  solver->SetStimulusStrength(2.0);
  solver->SetStimulusDuration(std::max(4.0, dt));
  solver->SetSolverTolerance(1e-10);
  solver->Update();
  vtkUnstructuredGrid* out = solver->GetOutput();
  const double t30 = ActivationAt(out, 30.0), t42 = ActivationAt(out, 42.0);
  EXPECT_GT(t30, 0);
  EXPECT_GT(t42, t30);
  return 12.0 / (t42 - t30);
}

const double Exact = std::sqrt(0.26 * 1.0 / 2.0) * (1.0 - 2.0 * 0.13); // mm/ms
}

TEST(FitzHughNagumo, PlaneWaveSpeedConvergesInSpace)
{
  // Orders from successive differences (the dt = 0.01 ms time error, about -0.03 %, is the same
  // for every h and cancels).
  const double hs[4] = { 1.0, 0.5, 0.25, 0.125 };
  double c[4];
  std::printf("plane wave, D = 1 mm^2/ms, k = 0.26/ms, a = 0.13: exact speed %.6f mm/ms (dt = 0.01 ms)\n", Exact);
  for (int k = 0; k < 4; ++k)
  {
    c[k] = PlaneWaveSpeed(hs[k], 0.01);
    std::printf("  h = %.3f mm: speed %.6f mm/ms, error against the exact speed %+.4f%%\n", hs[k], c[k],
      100 * (c[k] - Exact) / Exact);
  }
  for (int k = 0; k < 2; ++k)
  {
    const double order = std::log(std::fabs(c[k] - c[k + 1]) / std::fabs(c[k + 1] - c[k + 2])) / std::log(2.0);
    std::printf("  observed order in space (h = %.3f, %.3f, %.3f): %.2f\n", hs[k], hs[k + 1], hs[k + 2], order);
    EXPECT_GT(order, 1.7); // second order
    EXPECT_LT(order, 2.5);
  }
  EXPECT_LT(std::fabs(c[3] - Exact) / Exact, 0.03);  // within 3 % on the finest mesh
  EXPECT_LT(std::fabs(c[3] - Exact) / Exact, 0.001); // what it does: within 0.1 %
}

TEST(FitzHughNagumo, PlaneWaveSpeedConvergesInTime)
{
  const double dts[4] = { 0.4, 0.2, 0.1, 0.05 };
  double c[4];
  std::printf("plane wave at h = 0.25 mm:\n");
  for (int k = 0; k < 4; ++k)
  {
    c[k] = PlaneWaveSpeed(0.25, dts[k]);
    std::printf("  dt = %.3f ms: speed %.6f mm/ms, error against the exact speed %+.4f%%\n", dts[k], c[k],
      100 * (c[k] - Exact) / Exact);
  }
  for (int k = 0; k < 2; ++k)
  {
    const double order = std::log(std::fabs(c[k] - c[k + 1]) / std::fabs(c[k + 1] - c[k + 2])) / std::log(2.0);
    std::printf("  observed order in time (dt = %.3f, %.3f, %.3f): %.2f\n", dts[k], dts[k + 1], dts[k + 2], order);
    EXPECT_GT(order, 0.8); // first order (semi-implicit Euler)
    EXPECT_LT(order, 1.3);
  }
  EXPECT_LT(std::fabs(c[0] - Exact) / Exact, 0.03); // even the 0.4 ms step is within 3 %
}

TEST(FitzHughNagumo, NiedererSlabActivation)
{
  // 20 x 7 x 3 mm, fibers along x (transverse conductivity ratio 0.019/0.17 as in Niederer et al.
  // 2011), stimulus at the corner; activation at P1 (corner), the centre and P8 (far corner).
  double previous = -1;
  for (double dx : { 0.5, 0.25 })
  {
    vtkNew<amFitzHughNagumoSolver> solver;
    amTest::NiedererSlab(dx, solver, 0.05, 100);
    solver->Update();
    vtkUnstructuredGrid* out = solver->GetOutput();
    vtkDataArray* act = out->GetPointData()->GetArray("ActivationTime");
    auto at = [&](double x, double y, double z) {
      const double p[3] = { x, y, z };
      return act->GetComponent(out->FindPoint(p[0], p[1], p[2]), 0);
    };
    const double p1 = at(0, 0, 0), centre = at(10, 3.5, 1.5), p8 = at(20, 7, 3);
    std::printf(
      "Niederer-style slab dx = %.2f mm, dt = 0.05 ms: P1 %.2f ms, centre %.2f ms, P8 %.2f ms\n", dx, p1, centre, p8);
    EXPECT_DOUBLE_EQ(solver->GetActivatedFraction(), 1.0);
    // The far corner is not always last: fronts run faster along the no-flux walls than through the
    // middle, as in the benchmark's own solutions; the corner of the stimulus is first.
    EXPECT_LT(p1, centre);
    EXPECT_LT(p1, p8);
    if (previous > 0)
      EXPECT_LT(std::fabs(p8 - previous) / p8, 0.1);
    previous = p8;
  }
}

TEST(FitzHughNagumo, TimeDependentOutputAndFullCycle)
{
  const int n[3] = { 30, 6, 2 };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 30, 6, 2 };
  auto mesh = amTest::BoxMesh(n, origin, size);
  vtkNew<amFitzHughNagumoSolver> solver;
  solver->SetInputData(mesh);
  solver->RemoveAllHeartRegions();
  solver->AddHeartRegion(1);
  solver->SetTimeStep(1.0); // the paper's step
  solver->SetEndTime(500);
  solver->SetOutputInterval(10);
  solver->SetStimulusCenter(0, 3, 1);
  solver->SetStimulusRadius(4);
  solver->SetStimulusDuration(4);
  solver->UpdateInformation();
  vtkInformation* info = solver->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  EXPECT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 51);
  solver->UpdateTimeStep(23.0); // answered by the frame at 20 ms
  vtkUnstructuredGrid* out = solver->GetOutput();
  EXPECT_DOUBLE_EQ(out->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), 20.0);
  vtkDataArray* act = out->GetPointData()->GetArray("ActivationTime");
  vtkDataArray* u = out->GetPointData()->GetArray("u");
  double maxU = 0;
  int notYet = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    maxU = std::max(maxU, u->GetComponent(i, 0));
    notYet += act->GetComponent(i, 0) < 0;
    if (act->GetComponent(i, 0) >= 0)
      EXPECT_LE(act->GetComponent(i, 0), 20.0);
  }
  EXPECT_GT(maxU, 0.5);
  EXPECT_GT(notYet, 0); // the far end is not reached at 20 ms
  const double wall = solver->GetWallSeconds();

  // At 500 ms every node has depolarised and recovered (u back near rest).
  solver->UpdateTimeStep(500.0);
  out = solver->GetOutput();
  EXPECT_DOUBLE_EQ(solver->GetWallSeconds(), wall); // answered from the kept frames, no new run
  EXPECT_DOUBLE_EQ(solver->GetActivatedFraction(), 1.0);
  act = out->GetPointData()->GetArray("ActivationTime");
  u = out->GetPointData()->GetArray("u");
  double maxU500 = 0, minAct = 1e9;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    maxU500 = std::max(maxU500, std::fabs(u->GetComponent(i, 0)));
    minAct = std::min(minAct, act->GetComponent(i, 0));
    // Activation time grows with the distance from the stimulus corner (x dominates here).
  }
  EXPECT_GE(minAct, 0.0);
  EXPECT_LT(maxU500, 0.1);
  const double p0[3] = { 5, 0, 0 }, p1[3] = { 15, 0, 0 }, p2[3] = { 25, 0, 0 };
  const double a0 = act->GetComponent(out->FindPoint(p0[0], p0[1], p0[2]), 0),
               a1 = act->GetComponent(out->FindPoint(p1[0], p1[1], p1[2]), 0),
               a2 = act->GetComponent(out->FindPoint(p2[0], p2[1], p2[2]), 0);
  EXPECT_LT(a0, a1);
  EXPECT_LT(a1, a2);
}

namespace
{
/// A slab of n cells over 'size' mm from the origin: a "blood pool" (region 6) for x < 6, the
/// heart (region 5) beyond, activated from region 6 (spreading from 'centre' at 'velocity' mm/ms,
/// 0: at once) and run to 'end' ms. A single layer of nodes drains into the wall: it needs more
/// charge (StimulusStrength 2) than a sphere of 10 mm.
vtkSmartPointer<amFitzHughNagumoSolver> EndocardialSlab(
  const int n[3], const double size[3], const double centre[3], double velocity, double end)
{
  const double origin[3] = { 0, 0, 0 };
  auto mesh = amTest::BoxMesh(n, origin, size, [](const double* c) { return c[0] < 6 ? 6 : 5; });
  auto solver = vtkSmartPointer<amFitzHughNagumoSolver>::New();
  solver->SetInputData(mesh);
  solver->AddEndocardialRegion(6);
  solver->SetEndocardialConductionVelocity(velocity);
  solver->SetStimulusCenter(centre[0], centre[1], centre[2]);
  solver->SetStimulusStrength(2);
  solver->SetTimeStep(0.5);
  solver->SetEndTime(end);
  solver->SetOutputInterval(10);
  solver->UpdateTimeStep(end);
  return solver;
}
}

TEST(FitzHughNagumo, EndocardialRegionsActivateTheHeartFromInside)
{
  // A slab x in [0, 30] mm: a "blood pool" (region 6) for x < 6, the heart (region 5) beyond.
  // With EndocardialRegions 6 the heart starts at its face x = 6 at once: activation grows with
  // x alone (a plane wave), and no stimulus sphere is needed.
  const int n[3] = { 30, 4, 2 };
  const double size[3] = { 30, 4, 2 };
  const double far[3] = { 1000, 1000, 1000 }; // the stimulus centre, ignored without a velocity
  auto solver = EndocardialSlab(n, size, far, 0.0, 80);
  vtkUnstructuredGrid* out = solver->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  vtkDataArray* act = out->GetPointData()->GetArray("ActivationTime");
  auto at = [&](double x, double y) { return act->GetComponent(out->FindPoint(x, y, 1), 0); };
  EXPECT_LT(at(6, 0), 5.0); // the endocardial face: within the stimulus
  EXPECT_NEAR(at(6, 0), at(6, 4), 0.5);
  EXPECT_LT(at(6, 2), at(16, 2));
  EXPECT_LT(at(16, 2), at(26, 2));
  EXPECT_NEAR(at(16, 0), at(16, 4), 0.5); // a plane wave
  EXPECT_DOUBLE_EQ(solver->GetActivatedFraction(), 1.0);
}

TEST(FitzHughNagumo, EndocardialActivationSpreadsAtItsConductionVelocity)
{
  // The slab's endocardial face x = 6 is 40 mm long in y. Spreading from (6, 0, 1) at 2 mm/ms, the
  // stimulus at y starts y / 2 ms after the near end's (the wall conducts slower, so nothing
  // reaches a node before its own stimulus does); at once (velocity 0), all start together.
  const int n[3] = { 16, 40, 2 };
  const double size[3] = { 16, 40, 2 };
  const double centre[3] = { 6, 0, 1 };
  for (double velocity : { 2.0, 0.0 })
  {
    auto solver = EndocardialSlab(n, size, centre, velocity, 60);
    vtkUnstructuredGrid* out = solver->GetOutput();
    ASSERT_GT(out->GetNumberOfPoints(), 0);
    vtkDataArray* act = out->GetPointData()->GetArray("ActivationTime");
    auto at = [&](double x, double y) { return act->GetComponent(out->FindPoint(x, y, 1), 0); };
    std::printf("velocity %.0f mm/ms: activation at y = 0, 20, 40: %.2f, %.2f, %.2f ms\n", velocity, at(6, 0),
      at(6, 20), at(6, 40));
    for (double y : { 0.0, 20.0, 40.0 })
    {
      // Each node within a few ms after its own stimulus starts (sooner where its neighbours
      // along the face are already active), never before it.
      const double onset = velocity > 0 ? y / velocity : 0.0;
      EXPECT_GE(at(6, y), onset) << y;
      EXPECT_LE(at(6, y), onset + 2.5) << y;
    }
    if (velocity > 0)
      EXPECT_GT(at(6, 40) - at(6, 0), 15.0);
    else
      EXPECT_LT(std::fabs(at(6, 40) - at(6, 0)), 0.5);
    EXPECT_DOUBLE_EQ(solver->GetActivatedFraction(), 1.0);
  }
}

TEST(FitzHughNagumo, SameInputSameResult)
{
  const int n[3] = { 20, 4, 2 };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 20, 4, 2 };
  std::vector<double> runs[2];
  for (auto& r : runs)
  {
    auto mesh = amTest::BoxMesh(n, origin, size);
    vtkNew<amFitzHughNagumoSolver> solver;
    solver->SetInputData(mesh);
    solver->RemoveAllHeartRegions();
    solver->AddHeartRegion(1);
    solver->SetEndTime(30);
    solver->SetStimulusCenter(0, 0, 0);
    solver->Update();
    vtkDataArray* u = solver->GetOutput()->GetPointData()->GetArray("u");
    for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
      r.push_back(u->GetComponent(i, 0));
  }
  EXPECT_EQ(runs[0], runs[1]);
}

namespace
{
std::string SolveExpectingError(vtkUnstructuredGrid* mesh, const std::function<void(amFitzHughNagumoSolver*)>& set)
{
  vtkNew<amFitzHughNagumoSolver> solver;
  vtkNew<amTest::ErrorCatcher> catcher;
  catcher->Watch(solver);
  catcher->Watch(solver->GetExecutive());
  solver->SetInputData(mesh);
  solver->RemoveAllHeartRegions();
  solver->AddHeartRegion(1);
  solver->SetEndTime(5);
  set(solver);
  solver->Update();
  EXPECT_TRUE(catcher->HasError());
  EXPECT_EQ(solver->GetOutput()->GetNumberOfPoints(), 0); // nothing written
  return catcher->AllErrors();
}
}

TEST(FitzHughNagumo, BadInput)
{
  const int n[3] = { 4, 4, 4 };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 4, 4, 4 };
  auto mesh = amTest::BoxMesh(n, origin, size);
  std::string e = SolveExpectingError(mesh, [](amFitzHughNagumoSolver* s) {
    s->RemoveAllHeartRegions();
    s->AddHeartRegion(5);
  });
  EXPECT_NE(e.find("no heart"), std::string::npos) << e;
  e = SolveExpectingError(mesh, [](amFitzHughNagumoSolver* s) { s->SetStimulusCenter(100, 0, 0); });
  EXPECT_NE(e.find("stimulus is outside the heart"), std::string::npos) << e;
  e = SolveExpectingError(mesh, [](amFitzHughNagumoSolver* s) { s->SetTimeStep(10); });
  EXPECT_NE(e.find("too large for stability"), std::string::npos) << e;
  e = SolveExpectingError(mesh, [](amFitzHughNagumoSolver* s) {
    s->SetTimeStep(1);
    s->SetStimulusDuration(0.5);
  });
  EXPECT_NE(e.find("less than one time step"), std::string::npos) << e;
  // A collapsed tetrahedron: move one point onto another.
  auto bad = amTest::BoxMesh(n, origin, size);
  double p[3];
  bad->GetPoint(1, p);
  bad->GetPoints()->SetPoint(0, p);
  e = SolveExpectingError(bad, [](amFitzHughNagumoSolver*) {});
  EXPECT_NE(e.find("degenerate"), std::string::npos) << e;
  // A NaN coordinate.
  auto nan = amTest::BoxMesh(n, origin, size);
  nan->GetPoints()->SetPoint(7, std::nan(""), 0, 0);
  e = SolveExpectingError(nan, [](amFitzHughNagumoSolver*) {});
  EXPECT_NE(e.find("degenerate"), std::string::npos) << e;
}

namespace
{
// Landmarks as amCardiacLandmarks gives them: points with point data "Name".
vtkSmartPointer<vtkPolyData> Landmarks(const std::vector<std::pair<std::string, std::array<double, 3>>>& points)
{
  auto landmarks = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> xyz;
  vtkNew<vtkStringArray> names;
  names->SetName("Name");
  for (const auto& [name, x] : points)
  {
    xyz->InsertNextPoint(x.data());
    names->InsertNextValue(name);
  }
  landmarks->SetPoints(xyz);
  landmarks->GetPointData()->AddArray(names);
  return landmarks;
}
}

TEST(FitzHughNagumo, TheLandmarksStimulusIsTheStimulusCentre)
{
  const int n[3] = { 20, 4, 2 };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 20, 4, 2 };
  auto mesh = amTest::BoxMesh(n, origin, size);
  std::vector<double> runs[2];
  for (int run = 0; run < 2; ++run)
  {
    vtkNew<amFitzHughNagumoSolver> solver;
    solver->SetInputData(mesh);
    solver->RemoveAllHeartRegions();
    solver->AddHeartRegion(1);
    solver->SetEndTime(20);
    if (run == 0)
      solver->SetStimulusCenter(20, 4, 2);
    else
      solver->SetInputData(1, Landmarks({ { "V1", { 0, 0, 0 } }, { "Stimulus", { 20, 4, 2 } } }));
    solver->Update();
    vtkDataArray* t = solver->GetOutput()->GetPointData()->GetArray("ActivationTime");
    for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
      runs[run].push_back(t->GetComponent(i, 0));
  }
  EXPECT_EQ(runs[0], runs[1]);
  // The far corner from the stimulus activates last.
  EXPECT_GT(runs[1][0], 5.0);

  // Landmarks without a stimulus are an error that says so.
  const std::string e = SolveExpectingError(mesh, [](amFitzHughNagumoSolver* s) {
    s->SetInputData(1, Landmarks({ { "V1", { 0, 0, 0 } } }));
  });
  EXPECT_NE(e.find("no point named Stimulus"), std::string::npos) << e;
}
