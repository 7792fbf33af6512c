/**
 * @class   amMonodomainStepper
 * @brief   The monodomain equation with any cell model behind amIonicModel, on P1 finite elements:
 *          dVm/dt = div(D grad Vm) + I_ion(Vm, gates) + I_stim, zero flux on the boundary.
 *
 * Vm in mV, time in ms, D in mm^2/ms per tetrahedron (xx yy zz xy yz xz). Each step splits the
 * operators as amFitzHughNagumoStepper does: the cell model's own step at every node (gates, then
 * Vm with the ionic current and the stimulus), then the diffusion implicitly, (M + dt K) Vm = M w,
 * with the matrix factored once (sparse Cholesky). A node's activation time is where Vm first
 * crosses ActivationThreshold upwards, interpolated within the step. The reference the eikonal is
 * verified against (TestReactionEikonal), and the way to a fully coupled heartbeat on fine meshes.
 */
#ifndef amMonodomainStepper_h
#define amMonodomainStepper_h

#include "amSparseCholesky.h"
#include "amSparseMatrix.h"

#include <array>
#include <string>
#include <vector>

class amIonicModel;
class amP1Assembly;

class amMonodomainStepper
{
public:
  struct Parameters
  {
    double TimeStep = 0.02;                                                // ms
    double ActivationThreshold = -35.0;                                    // mV
    double StimulusStart = 0, StimulusDuration = 1, StimulusStrength = 60; // ms, ms, mV/ms
  };

  /// Assembles and factors M + dt K, starts every node at rest. 'local': per node, the cell
  /// model's local parameter (empty: its default).
  bool Setup(const amP1Assembly& fem, const std::vector<std::array<double, 6>>& tensors,
    const std::vector<unsigned char>& stimulated, const amIonicModel& model, const Parameters& parameters,
    const std::vector<double>& local = std::vector<double>());
  /// One step from t to t + dt.
  bool Step(double t);

  std::vector<double> Vm, Gates, Activation; // per node (Gates: NumberOfGates per node)
  std::string Error;

private:
  const amIonicModel* Model = nullptr;
  Parameters P;
  amSparseMatrix M, K, S;
  amSparseCholesky Factor;
  std::vector<unsigned char> Stimulated;
  std::vector<double> Local, W, B, Old;
};

#endif
