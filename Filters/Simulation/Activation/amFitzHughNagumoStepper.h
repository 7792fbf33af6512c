/**
 * @class   amFitzHughNagumoStepper
 * @brief   The time stepper of the FitzHugh-Nagumo (Rogers-McCulloch) monodomain model on P1
 *          finite elements, without the pipeline: one step from t to t + dt at a time.
 *
 *   du/dt = div(sigma grad u) + c1 u (u - a)(1 - u) - c2 u v + I_stim,   dv/dt = c3 (u - c4 v)
 *
 * Operator splitting per step: the reaction explicitly (w = u + dt f(u, v), the stimulus on the
 * stimulated nodes), the diffusion implicitly ((M + dt K) u = M w, conjugate gradients from the
 * last u), the recovery implicitly in v (v = (v + dt c3 u) / (1 + dt c3 c4)). A node's activation
 * time is where u first crosses the threshold upwards, interpolated linearly within the step.
 *
 * References: J. M. Rogers and A. D. McCulloch, A collocation-Galerkin finite element model of
 * cardiac action potential propagation, IEEE TBME 41(8), 1994; the CEMRACS 2004 paper's case study.
 *
 * @sa amFitzHughNagumoSolver amP1Assembly
 */
#ifndef amFitzHughNagumoStepper_h
#define amFitzHughNagumoStepper_h

#include "AnatomeshFiltersSimulationModule.h" // export macro
#include "amConjugateGradient.h"
#include "amSparseCholesky.h"
#include "amSparseMatrix.h"

#include <array>
#include <string>
#include <vector>

class amP1Assembly;

class ANATOMESHFILTERSSIMULATION_EXPORT amFitzHughNagumoStepper
{
public:
  struct Parameters
  {
    double C1 = 0.26, C2 = 0.1, C3 = 0.013, C4 = 1.0, A = 0.13;
    double TimeStep = 0.5; // ms
    double ActivationThreshold = 0.5;
    double StimulusStart = 0, StimulusDuration = 5, StimulusStrength = 1; // ms, ms, 1/ms
    bool Direct = true; // M + dt K factored once (else conjugate gradients at every step)
    double SolverTolerance = 1e-8;
    int MaximumIterations = 1000;
  };

  /// The largest stable time step (ms) of the explicit reaction: dt |df/du| <= 2 for u in
  /// [-0.05, 1.05] and v in [0, 1].
  static double StableTimeStep(double c1, double c2, double a);

  /// Assembles the matrices of the mesh (tensors: the conductivity per tetrahedron, xx yy zz xy
  /// yz xz) and starts from rest (u = v = 0, no activation). 'stimulated': per node, 1 where the
  /// stimulus applies; 'delays' (empty: none): per node, ms after StimulusStart when its stimulus
  /// starts (it then lasts StimulusDuration).
  void Setup(const amP1Assembly& fem, const std::vector<std::array<double, 6>>& tensors,
    const std::vector<unsigned char>& stimulated, const Parameters& parameters,
    const std::vector<double>& delays = std::vector<double>());
  /// One step from time t to t + dt (the implicit diffusion solved with the factor of M + dt K
  /// when Parameters::Direct, else, or where that factor could not be made, by conjugate
  /// gradients). False when the conjugate gradients did not converge (Error says how far they got).
  bool Step(double t);

  std::vector<double> U, V;       // per node
  std::vector<double> Activation; // per node: the activation time (ms), -1 before it
  long long Iterations = 0;       // conjugate-gradient iterations so far (none with the factor)
  std::string Error;

private:
  Parameters P;
  amSparseMatrix M, K, S;
  amConjugateGradient Solver;
  // The step's matrix M + dt K factored once: each step is then two triangular sweeps instead of
  // a dozen conjugate-gradient iterations.
  amSparseCholesky Factor;
  bool Factored = false;
  std::vector<unsigned char> Stimulated;
  std::vector<double> Delays;
  std::vector<double> W, B, UOld;
};

#endif
