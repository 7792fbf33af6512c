#include "amActionPotentialTable.h"

#include "amMitchellSchaeffer.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <sstream>

std::size_t amActionPotentialTable::Bin(double apd) const
{
  const double k = std::round((apd - this->First) / this->Resolution);
  return static_cast<std::size_t>(std::min<double>(std::max(0.0, k), static_cast<double>(this->Traces.size() - 1)));
}

bool amActionPotentialTable::Build(
  const amMitchellSchaeffer& model, const std::vector<double>& durations, double length)
{
  this->Traces.clear();
  this->Parameters.clear();
  this->Rest = model.RestingPotential();
  if (durations.empty())
    return true;
  const auto range = std::minmax_element(durations.begin(), durations.end());
  this->First = *range.first;
  const std::size_t bins = static_cast<std::size_t>(std::round((*range.second - this->First) / this->Resolution)) + 1;
  this->Traces.assign(bins, {});
  this->Integrals.assign(bins, {});
  this->Parameters.assign(bins, 0.0);
  const double dt = this->TimeStep;
  const std::size_t samples = static_cast<std::size_t>(std::ceil(length / dt)) + 2;
  const double span = model.PeakVoltage - model.RestVoltage;
  vtkSMPTools::For(0, static_cast<vtkIdType>(bins), 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0; b < b1; ++b)
    {
      const double apd = this->First + this->Resolution * b;
      const double local = model.CloseTimeFor(apd, dt, this->StimulusDuration, this->StimulusStrength);
      this->Parameters[b] = local;
      if (local <= 0)
        continue;
      // Stepped from the stimulus until the upstroke, then kept sample by sample after it.
      double vm = model.RestVoltage, h;
      model.Rest(&h);
      double t = 0, previous = vm;
      const double half = model.RestVoltage + 0.5 * span;
      while (vm < half && t < 50)
      {
        previous = vm;
        model.Step(dt, t < this->StimulusDuration - 1e-9 ? this->StimulusStrength : 0.0, local, vm, &h);
        t += dt;
      }
      // The upstroke lies 'late' ms before the current time t; the trace starts there.
      const double late = vm > previous ? dt * (vm - half) / (vm - previous) : 0.0;
      std::vector<float>& trace = this->Traces[b];
      trace.reserve(samples);
      // Sample k of the trace is at 'k dt' after the upstroke: interpolate the stepped voltages.
      double before = previous, after = vm;
      double clock = t; // time of 'after'
      const double upstroke = t - late;
      for (std::size_t k = 0; k < samples; ++k)
      {
        const double want = upstroke + k * dt;
        while (clock < want)
        {
          before = after;
          model.Step(dt, clock < this->StimulusDuration - 1e-9 ? this->StimulusStrength : 0.0, local, after, &h);
          clock += dt;
        }
        const double w = (clock - want) / dt;
        trace.push_back(static_cast<float>(w * before + (1 - w) * after));
      }
      std::vector<double>& integral = this->Integrals[b];
      integral.resize(trace.size());
      integral[0] = 0.0;
      for (std::size_t k = 1; k < trace.size(); ++k)
        integral[k] = integral[k - 1] + 0.5 * dt * (static_cast<double>(trace[k - 1]) + trace[k]);
    }
  });
  for (std::size_t b = 0; b < bins; ++b)
    if (this->Parameters[b] <= 0)
    {
      std::ostringstream why;
      why << "the " << model.Name() << " model gives no action potential of " << this->First + this->Resolution * b
          << " ms";
      this->Error = why.str();
      return false;
    }
  return true;
}

double amActionPotentialTable::Integral(std::size_t bin, double since) const
{
  // The integral of the voltage from the upstroke to 'since' (negative before it: rest).
  if (since <= 0)
    return this->Rest * since;
  const std::vector<float>& trace = this->Traces[bin];
  const std::vector<double>& integral = this->Integrals[bin];
  const double x = since / this->TimeStep;
  const std::size_t k = static_cast<std::size_t>(x);
  if (k + 1 >= trace.size())
    return integral.back() + trace.back() * (since - this->TimeStep * (trace.size() - 1));
  const double w = x - k;
  // Exact for the linear interpolation between samples k and k + 1.
  return integral[k] + this->TimeStep * w * (trace[k] + 0.5 * w * (trace[k + 1] - trace[k]));
}

double amActionPotentialTable::Voltage(double apd, double since, double spread) const
{
  if (this->Traces.empty() || !std::isfinite(since))
    return this->Rest;
  if (spread > this->TimeStep)
  {
    const std::size_t bin = this->Bin(apd);
    return (this->Integral(bin, since + 0.5 * spread) - this->Integral(bin, since - 0.5 * spread)) / spread;
  }
  if (!(since >= 0))
    return this->Rest;
  const std::vector<float>& trace = this->Traces[this->Bin(apd)];
  const double x = since / this->TimeStep;
  const std::size_t k = static_cast<std::size_t>(x);
  if (k + 1 >= trace.size())
    return trace.back();
  const double w = x - k;
  return (1 - w) * trace[k] + w * trace[k + 1];
}
