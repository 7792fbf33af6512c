/**
 * @class   amMitchellSchaeffer
 * @brief   The Mitchell-Schaeffer two-variable cell model: an action potential with a plateau and
 *          a repolarisation whose duration is set by one time constant.
 *
 *   dv/dt = h v^2 (1 - v) / tau_in - v / tau_out + J_stim
 *   dh/dt = (1 - h) / tau_open   where v <  v_gate
 *   dh/dt = -h / tau_close       where v >= v_gate
 *
 * v is dimensionless (0 at rest, about 1 at the peak), mapped to Vm = V_rest + (V_peak - V_rest) v
 * (-85 to +15 mV by default); time in ms. Defaults: tau_in 0.3, tau_out 6, tau_open 120, tau_close
 * 150 ms, v_gate 0.13 (Mitchell and Schaeffer 2003). The action potential duration grows with
 * tau_close (about tau_close ln(tau_out / (4 tau_in))); CloseTimeFor() inverts the measured one.
 * The gate is integrated exactly over a step (it is linear in h at fixed v), v by forward Euler.
 *
 * Reference: C. C. Mitchell and D. G. Schaeffer, A two-current model for the dynamics of cardiac
 * membrane, Bull. Math. Biol. 65:767-793, 2003.
 */
#ifndef amMitchellSchaeffer_h
#define amMitchellSchaeffer_h

#include "amIonicModel.h"

#include <vector>

class amMitchellSchaeffer : public amIonicModel
{
public:
  double TauIn = 0.3, TauOut = 6.0, TauOpen = 120.0, TauClose = 150.0, VGate = 0.13; // ms, dimensionless
  double RestVoltage = -85.0, PeakVoltage = 15.0;                                    // mV

  const char* Name() const override { return "Mitchell-Schaeffer"; }
  int NumberOfGates() const override { return 1; }
  double RestingPotential() const override { return this->RestVoltage; }
  void Rest(double* gates) const override { gates[0] = 1.0; }
  /// 'local' is tau_close (ms); 0 takes TauClose.
  void Step(double dt, double stimulus, double local, double& vm, double* gates) const override;
  double StableTimeStep() const override;

  /// The action potential duration (ms, to 90 % repolarisation) of a resting cell stimulated at
  /// t = 0 for 'duration' ms at 'strength' mV/ms, with closing time tauClose, stepped at dt.
  double Duration(double tauClose, double dt, double duration, double strength) const;
  /// The closing time whose Duration() is 'apd' ms (bisection); 0 when no closing time in [1, 5000] ms
  /// gives it.
  double CloseTimeFor(double apd, double dt, double duration, double strength) const;
};

#endif
