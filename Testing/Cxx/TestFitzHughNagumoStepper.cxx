// The FitzHugh-Nagumo time stepper without a pipeline: a uniform state follows the reaction ODE
// (diffusion leaves a uniform field alone), computed here independently step by step.
#include "amFitzHughNagumoStepper.h"
#include "amSimulationTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// A 4 x 3 x 3 mm box of tetrahedra (1 mm) as finite elements, isotropic conductivity 0.1.
struct Box
{
  amP1Assembly Fem;
  std::vector<std::array<double, 6>> Tensors;
  Box()
  {
    const int n[3] = { 5, 4, 4 };
    const double origin[3] = { 0, 0, 0 }, size[3] = { 4, 3, 3 };
    this->Fem = amTest::FemOf(amTest::BoxMesh(n, origin, size));
    const double f[3] = { 0, 0, 0 };
    this->Tensors.assign(this->Fem.Tetrahedra.size(), amP1Assembly::FiberTensor(0.1, 0.1, f));
  }
};
}

TEST(FitzHughNagumoStepper, UniformStateFollowsTheReaction)
{
  const Box box;
  amFitzHughNagumoStepper::Parameters p;
  p.TimeStep = 0.1;
  p.StimulusDuration = 2;
  p.SolverTolerance = 1e-12;
  amFitzHughNagumoStepper stepper;
  stepper.Setup(box.Fem, box.Tensors, std::vector<unsigned char>(box.Fem.Points.size(), 1), p);
  // The same scheme for one node: explicit reaction, implicit recovery.
  double u = 0, v = 0, activation = -1;
  for (int s = 0; s < 400; ++s)
  {
    const double t = s * p.TimeStep;
    ASSERT_TRUE(stepper.Step(t)) << stepper.Error;
    const double stim = t < p.StimulusDuration - 1e-9 ? p.StimulusStrength : 0.0;
    const double old = u;
    u += p.TimeStep * (p.C1 * u * (u - p.A) * (1 - u) - p.C2 * u * v + stim);
    v = (v + p.TimeStep * p.C3 * u) / (1 + p.TimeStep * p.C3 * p.C4);
    if (activation < 0 && old < p.ActivationThreshold && u >= p.ActivationThreshold)
      activation = t + p.TimeStep * (p.ActivationThreshold - old) / (u - old);
    for (size_t i = 0; i < stepper.U.size(); i += 7)
    {
      ASSERT_NEAR(stepper.U[i], u, 1e-8) << "node " << i << " at t = " << t + p.TimeStep;
      ASSERT_NEAR(stepper.V[i], v, 1e-8) << "node " << i;
    }
  }
  ASSERT_GT(activation, 0);
  EXPECT_LT(activation, 3.0); // the 2 ms stimulus at 1/ms lifts u over 0.5 within a few ms
  for (double a : stepper.Activation)
    EXPECT_NEAR(a, activation, 1e-8);
  EXPECT_GT(u, 0.5); // still depolarised at 40 ms (the plateau lasts hundreds of ms)
}

TEST(FitzHughNagumoStepper, RestStaysAtRestAndWavesSpread)
{
  const Box box;
  amFitzHughNagumoStepper::Parameters p;
  amFitzHughNagumoStepper rest;
  rest.Setup(box.Fem, box.Tensors, std::vector<unsigned char>(box.Fem.Points.size(), 0), p);
  for (int s = 0; s < 20; ++s)
    ASSERT_TRUE(rest.Step(s * p.TimeStep));
  for (double u : rest.U)
    EXPECT_EQ(u, 0.0);
  // Stimulated at the x = 0 end only: the far end activates later than the near one.
  std::vector<unsigned char> end(box.Fem.Points.size(), 0);
  for (size_t i = 0; i < end.size(); ++i)
    end[i] = box.Fem.Points[i][0] < 0.5;
  amFitzHughNagumoStepper wave;
  wave.Setup(box.Fem, box.Tensors, end, p);
  for (int s = 0; s < 200; ++s)
    ASSERT_TRUE(wave.Step(s * p.TimeStep));
  double nearest = 1e9, farthest = -1;
  for (size_t i = 0; i < end.size(); ++i)
  {
    ASSERT_GE(wave.Activation[i], 0) << "node " << i << " never activated";
    if (box.Fem.Points[i][0] < 0.5)
      nearest = std::min(nearest, wave.Activation[i]);
    if (box.Fem.Points[i][0] > 3.5)
      farthest = std::max(farthest, wave.Activation[i]);
  }
  EXPECT_GT(farthest, nearest + 1.0);
  EXPECT_EQ(wave.Iterations, 0); // the factor solves each step

  // The conjugate gradients (to 1e-12) reach the factor's states and activation times.
  amFitzHughNagumoStepper::Parameters q = p;
  q.Direct = false;
  q.SolverTolerance = 1e-12;
  amFitzHughNagumoStepper iterative;
  iterative.Setup(box.Fem, box.Tensors, end, q);
  for (int s = 0; s < 200; ++s)
    ASSERT_TRUE(iterative.Step(s * q.TimeStep));
  EXPECT_GT(iterative.Iterations, 0);
  double du = 0, dt = 0;
  for (size_t i = 0; i < end.size(); ++i)
  {
    du = std::max(du, std::fabs(iterative.U[i] - wave.U[i]));
    dt = std::max(dt, std::fabs(iterative.Activation[i] - wave.Activation[i]));
  }
  EXPECT_LT(du, 1e-8);
  EXPECT_LT(dt, 1e-6);
}

TEST(FitzHughNagumoStepper, StableTimeStepBoundsTheReaction)
{
  const double dt = amFitzHughNagumoStepper::StableTimeStep(0.26, 0.1, 0.13);
  EXPECT_GT(dt, 1.0);
  EXPECT_LT(dt, 10.0);
  EXPECT_EQ(amFitzHughNagumoStepper::StableTimeStep(0, 0, 0.13), 1e300);
}
