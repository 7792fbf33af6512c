#include "amMitchellSchaeffer.h"

#include <cmath>

void amMitchellSchaeffer::Step(double dt, double stimulus, double local, double& vm, double* gates) const
{
  const double span = this->PeakVoltage - this->RestVoltage;
  const double v = (vm - this->RestVoltage) / span;
  const double tauClose = local > 0 ? local : this->TauClose;
  double& h = gates[0];
  const double dv = h * v * v * (1.0 - v) / this->TauIn - v / this->TauOut;
  // The gate relaxes exponentially towards 1 (open) or 0 (closed) at fixed v: exact over the step.
  if (v < this->VGate)
    h = 1.0 - (1.0 - h) * std::exp(-dt / this->TauOpen);
  else
    h *= std::exp(-dt / tauClose);
  vm += dt * (span * dv + stimulus);
}

double amMitchellSchaeffer::StableTimeStep() const
{
  // |d(dv/dt)/dv| <= max over v in [0, 1] of |2v - 3v^2| / tau_in + 1 / tau_out = (1 / tau_in) + 1 / tau_out.
  return 2.0 / (1.0 / this->TauIn + 1.0 / this->TauOut);
}

double amMitchellSchaeffer::Duration(double tauClose, double dt, double duration, double strength) const
{
  double vm = this->RestVoltage, h = 1.0;
  const double span = this->PeakVoltage - this->RestVoltage;
  const double threshold = this->RestVoltage + 0.1 * span;
  double up = -1, t = 0;
  const double end = 20.0 * tauClose + 1000.0;
  while (t < end)
  {
    const double previous = vm;
    this->Step(dt, t < duration - 1e-9 ? strength : 0.0, tauClose, vm, &h);
    t += dt;
    if (up < 0 && previous < this->RestVoltage + 0.5 * span && vm >= this->RestVoltage + 0.5 * span)
      up = t - dt + dt * (this->RestVoltage + 0.5 * span - previous) / (vm - previous);
    if (up >= 0 && previous >= threshold && vm < threshold)
      return t - dt + dt * (previous - threshold) / (previous - vm) - up;
  }
  return -1.0;
}

double amMitchellSchaeffer::CloseTimeFor(double apd, double dt, double duration, double strength) const
{
  double lo = 1.0, hi = 5000.0;
  if (this->Duration(lo, dt, duration, strength) > apd || this->Duration(hi, dt, duration, strength) < apd)
    return 0.0;
  for (int k = 0; k < 50 && hi - lo > 1e-6; ++k)
  {
    const double mid = 0.5 * (lo + hi);
    (this->Duration(mid, dt, duration, strength) < apd ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
