/**
 * @class   amIonicModel
 * @brief   The interface of a cell model: the transmembrane voltage's ionic current and the gates
 *          that drive it, for one cell at a time.
 *
 * A model holds its parameters; the state of a cell is its voltage Vm (mV) and NumberOfGates()
 * gate values. One step of dt ms is Step(): the gates first (their own update rule, e.g. Rush-Larsen),
 * then Vm by forward Euler with the ionic current and a stimulus (mV/ms). A per-cell parameter
 * 'local' selects the cell's action potential duration (what the model makes of it is its own:
 * Mitchell-Schaeffer's closing time). Models live one per file in Ionic/.
 */
#ifndef amIonicModel_h
#define amIonicModel_h

class amIonicModel
{
public:
  virtual ~amIonicModel() = default;
  virtual const char* Name() const = 0;
  virtual int NumberOfGates() const = 0;
  /// The resting voltage (mV) and the gates at rest.
  virtual double RestingPotential() const = 0;
  virtual void Rest(double* gates) const = 0;
  /// One step of dt ms of a cell: gates, then Vm, with 'stimulus' mV/ms added to dVm/dt.
  virtual void Step(double dt, double stimulus, double local, double& vm, double* gates) const = 0;
  /// The largest time step (ms) the explicit voltage update takes.
  virtual double StableTimeStep() const = 0;
};

#endif
