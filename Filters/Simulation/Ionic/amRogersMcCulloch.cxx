#include "amRogersMcCulloch.h"

#include <algorithm>
#include <cmath>

void amRogersMcCulloch::Step(double dt, double stimulus, double, double& vm, double* gates) const
{
  const double span = this->PeakVoltage - this->RestVoltage;
  const double u = (vm - this->RestVoltage) / span;
  double& v = gates[0];
  const double du = this->C1 * u * (u - this->A) * (1.0 - u) - this->C2 * u * v;
  v = (v + dt * this->C3 * u) / (1.0 + dt * this->C3 * this->C4);
  vm += dt * (span * du + stimulus);
}

double amRogersMcCulloch::StableTimeStep() const
{
  // |d(du/dt)/du| over u in [-0.05, 1.05], v in [0, 1]: as amFitzHughNagumoStepper::StableTimeStep.
  double worst = 0.0;
  for (int k = 0; k <= 110; ++k)
  {
    const double u = -0.05 + 0.01 * k;
    worst = std::max(worst, std::fabs(this->C1 * (-3 * u * u + 2 * (1 + this->A) * u - this->A)));
  }
  worst += this->C2;
  return worst > 0 ? 2.0 / worst : 1e300;
}
