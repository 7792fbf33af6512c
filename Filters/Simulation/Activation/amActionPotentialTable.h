/**
 * @class   amActionPotentialTable
 * @brief   The action potentials of a cell model for a range of durations, computed once and read
 *          at any time after activation: the reaction half of a reaction-eikonal model.
 *
 * Each duration (rounded to Resolution ms) gets the model's local parameter that gives it
 * (Mitchell-Schaeffer's closing time, by bisection on the measured APD90) and the model's voltage
 * after a stimulus, stepped at TimeStep and kept at every step. Time 0 of a trace is its upstroke
 * (Vm crossing half-way from rest to peak), so Voltage(apd, t - activation) is a cell's voltage at
 * time t; averaged over a window (Voltage's spread, from the traces' integrals) it is the voltage
 * of a front that crosses the cell's elements in that time. Traces are computed on threads, one per duration; the
 * result does not depend on threads.
 */
#ifndef amActionPotentialTable_h
#define amActionPotentialTable_h

#include <string>
#include <vector>

class amMitchellSchaeffer;

class amActionPotentialTable
{
public:
  double TimeStep = 0.05;        // ms
  double Resolution = 0.5;       // ms of duration between traces
  double StimulusDuration = 1.0; // ms
  double StimulusStrength = 60;  // mV/ms

  /// Traces for every duration in 'durations' (ms), each 'length' ms long after the upstroke.
  /// False with Error when the model cannot make one of them.
  bool Build(const amMitchellSchaeffer& model, const std::vector<double>& durations, double length);

  /// Vm (mV) of a cell of duration apd, 'since' ms after its upstroke (rest before it), averaged
  /// over 'spread' ms centred there (0: the trace itself): the upstroke of a front that takes
  /// 'spread' ms to cross the cell's elements.
  double Voltage(double apd, double since, double spread = 0.0) const;

  std::string Error;

private:
  double Rest = 0, First = 0;
  std::vector<std::vector<float>> Traces;     // per duration bin
  std::vector<std::vector<double>> Integrals; // per bin: the trace's integral from its upstroke
  double Integral(std::size_t bin, double since) const;
  std::vector<double> Parameters; // per duration bin
  std::size_t Bin(double apd) const;
};

#endif
