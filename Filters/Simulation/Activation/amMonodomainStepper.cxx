#include "amMonodomainStepper.h"

#include "amIonicModel.h"
#include "amP1Assembly.h"
#include "amThreading.h"

bool amMonodomainStepper::Setup(const amP1Assembly& fem, const std::vector<std::array<double, 6>>& tensors,
  const std::vector<unsigned char>& stimulated, const amIonicModel& model, const Parameters& parameters,
  const std::vector<double>& local)
{
  this->Model = &model;
  this->P = parameters;
  if (this->P.TimeStep > model.StableTimeStep())
  {
    this->Error = "the time step is beyond the cell model's stability limit";
    return false;
  }
  fem.Assemble(&tensors, this->M, this->K);
  this->S.Combine(1.0, this->M, this->P.TimeStep, this->K);
  this->Factor.BlasThreads = 1;
  if (!this->Factor.Factor(&this->S))
  {
    this->Error = this->Factor.Error();
    return false;
  }
  const std::size_t n = fem.Points.size();
  const int gates = model.NumberOfGates();
  this->Stimulated = stimulated;
  this->Local = local.empty() ? std::vector<double>(n, 0.0) : local;
  this->Vm.assign(n, model.RestingPotential());
  this->Gates.resize(n * gates);
  for (std::size_t i = 0; i < n; ++i)
    model.Rest(&this->Gates[i * gates]);
  this->Activation.assign(n, -1.0);
  this->W.resize(n);
  this->B.resize(n);
  return true;
}

bool amMonodomainStepper::Step(double t)
{
  const vtkIdType n = static_cast<vtkIdType>(this->Vm.size());
  const double dt = this->P.TimeStep;
  const bool on =
    t + 1e-9 * dt >= this->P.StimulusStart && t < this->P.StimulusStart + this->P.StimulusDuration - 1e-9 * dt;
  const double strength = on ? this->P.StimulusStrength : 0.0;
  const int gates = this->Model->NumberOfGates();
  const amIonicModel* model = this->Model;
  amThreading::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      double v = this->Vm[i];
      model->Step(dt, this->Stimulated[i] ? strength : 0.0, this->Local[i], v, &this->Gates[i * gates]);
      this->W[i] = v;
    }
  });
  this->M.Multiply(this->W.data(), this->B.data());
  this->Old = this->Vm;
  if (!this->Factor.Solve(this->B.data(), this->Vm.data()))
  {
    this->Error = "no workspace for the solve";
    return false;
  }
  const double theta = this->P.ActivationThreshold;
  for (vtkIdType i = 0; i < n; ++i)
    if (this->Activation[i] < 0 && this->Old[i] < theta && this->Vm[i] >= theta)
      this->Activation[i] = t + dt * (theta - this->Old[i]) / (this->Vm[i] - this->Old[i]);
  return true;
}
