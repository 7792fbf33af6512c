/**
 * @class   amRogersMcCulloch
 * @brief   The paper's cell model behind the cell-model interface: FitzHugh-Nagumo with the
 *          Rogers-McCulloch modification, u mapped to millivolts.
 *
 *   du/dt = c1 u (u - a)(1 - u) - c2 u v + J_stim,   dv/dt = c3 (u - c4 v)
 *
 * u is dimensionless (0 at rest, about 1 depolarised), Vm = V_rest + (V_peak - V_rest) u (-85 to
 * +15 mV). Defaults c1 0.26/ms, c2 0.1/ms, c3 0.013/ms, c4 1, a 0.13 (Rogers and McCulloch 1994, as
 * amFitzHughNagumoSolver). The recovery variable is stepped implicitly (linear in v), u explicitly.
 * No plateau and no duration to set: 'local' is ignored. amFitzHughNagumoSolver keeps its own
 * stepper (the paper's splitting); this model lets the monodomain stepper run the paper's cell.
 *
 * Reference: J. M. Rogers and A. D. McCulloch, IEEE TBME 41(8), 1994.
 */
#ifndef amRogersMcCulloch_h
#define amRogersMcCulloch_h

#include "amIonicModel.h"

class amRogersMcCulloch : public amIonicModel
{
public:
  double C1 = 0.26, C2 = 0.1, C3 = 0.013, C4 = 1.0, A = 0.13; // 1/ms, 1/ms, 1/ms, -, -
  double RestVoltage = -85.0, PeakVoltage = 15.0;             // mV

  const char* Name() const override { return "Rogers-McCulloch"; }
  int NumberOfGates() const override { return 1; }
  double RestingPotential() const override { return this->RestVoltage; }
  void Rest(double* gates) const override { gates[0] = 0.0; }
  void Step(double dt, double stimulus, double local, double& vm, double* gates) const override;
  double StableTimeStep() const override;
};

#endif
