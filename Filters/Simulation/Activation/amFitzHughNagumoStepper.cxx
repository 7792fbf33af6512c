#include "amFitzHughNagumoStepper.h"

#include "amP1Assembly.h"
#include "amThreading.h"

#include <algorithm>
#include <cmath>
#include <sstream>

double amFitzHughNagumoStepper::StableTimeStep(double c1, double c2, double a)
{
  // df/du = c1 (-3u^2 + 2(1+a)u - a) - c2 v; its largest magnitude over the range, plus c2.
  double worst = 0.0;
  for (int k = 0; k <= 110; ++k)
  {
    const double u = -0.05 + 0.01 * k;
    worst = std::max(worst, std::fabs(c1 * (-3 * u * u + 2 * (1 + a) * u - a)));
  }
  worst += c2;
  return worst > 0 ? 2.0 / worst : 1e300;
}

void amFitzHughNagumoStepper::Setup(const amP1Assembly& fem, const std::vector<std::array<double, 6>>& tensors,
  const std::vector<unsigned char>& stimulated, const Parameters& parameters, const std::vector<double>& delays)
{
  this->P = parameters;
  fem.Assemble(&tensors, this->M, this->K);
  this->S.Combine(1.0, this->M, this->P.TimeStep, this->K);
  this->Solver.SetMatrix(&this->S);
  this->Solver.RelativeTolerance = this->P.SolverTolerance;
  this->Solver.MaximumIterations = this->P.MaximumIterations;
  // One BLAS thread for the small factor too (the solves have one by default).
  this->Factor.BlasThreads = 1;
  this->Factored = this->P.Direct && this->Factor.Factor(&this->S);
  const size_t n = fem.Points.size();
  this->Stimulated = stimulated;
  this->Delays = delays;
  this->U.assign(n, 0.0);
  this->V.assign(n, 0.0);
  this->W.resize(n);
  this->B.resize(n);
  this->UOld.resize(n);
  this->Activation.assign(n, -1.0);
  this->Iterations = 0;
}

bool amFitzHughNagumoStepper::Step(double t)
{
  const vtkIdType n = static_cast<vtkIdType>(this->U.size());
  const double dt = this->P.TimeStep;
  const double c1 = this->P.C1, c2 = this->P.C2, c3 = this->P.C3, c4 = this->P.C4, a = this->P.A;
  const double theta = this->P.ActivationThreshold;
  const double start = this->P.StimulusStart, duration = this->P.StimulusDuration, strength = this->P.StimulusStrength;
  auto stimulus = [=](double delay) {
    return t + 1e-9 * dt >= start + delay && t < start + delay + duration - 1e-9 * dt ? strength : 0.0;
  };
  const double stim = stimulus(0.0);
  const double* up = this->U.data();
  const double* vp = this->V.data();
  double* wp = this->W.data();
  const unsigned char* sp = this->Stimulated.data();
  const double* dp = this->Delays.empty() ? nullptr : this->Delays.data();
  amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const double ui = up[i];
      const double s = sp[i] ? (dp ? stimulus(dp[i]) : stim) : 0.0;
      const double f = c1 * ui * (ui - a) * (1.0 - ui) - c2 * ui * vp[i] + s;
      wp[i] = ui + dt * f;
    }
  });
  this->M.Multiply(this->W.data(), this->B.data());
  this->UOld = this->U;
  if (this->Factored && !this->Factor.Solve(this->B.data(), this->U.data()))
    this->Factored = false; // no workspace: the conjugate gradients from here on
  const amConjugateGradient::Result result =
    this->Factored ? amConjugateGradient::Result{ 0, 0, 0, true } : this->Solver.Solve(this->B.data(), this->U.data());
  this->Iterations += result.Iterations;
  if (!result.Converged)
  {
    std::ostringstream why;
    why << "conjugate gradients did not converge at t = " << t + dt << " ms (" << result.Iterations
        << " iterations, residual " << result.ResidualNorm << " of " << result.RightHandSideNorm << ")";
    this->Error = why.str();
    return false;
  }
  double* vw = this->V.data();
  const double* uo = this->UOld.data();
  double* act = this->Activation.data();
  const double* un = this->U.data();
  amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      vw[i] = (vw[i] + dt * c3 * un[i]) / (1.0 + dt * c3 * c4);
      if (act[i] < 0 && uo[i] < theta && un[i] >= theta)
        act[i] = t + dt * (theta - uo[i]) / (un[i] - uo[i]);
    }
  });
  return true;
}
