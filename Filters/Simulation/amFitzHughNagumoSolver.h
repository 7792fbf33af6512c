/**
 * @class   amFitzHughNagumoSolver
 * @brief   The paper's heart model: FitzHugh-Nagumo with the Rogers-McCulloch modification and
 *          diffusion (monodomain), P1 finite elements on the heart's tetrahedra, time-dependent.
 *
 *   du/dt = div(Sigma grad u) + c1 u (u - a)(1 - u) - c2 u v + I_stim   on the heart regions
 *   dv/dt = c3 (u - c4 v),        zero flux on the heart's boundary,     u = v = 0 at t = 0
 *
 * u is the dimensionless transmembrane potential (0 at rest, about 1 when depolarised), v the
 * recovery variable; time in ms, lengths in mm, Sigma in mm^2/ms.
 *
 * Defaults: c1 = 0.26/ms, c2 = 0.1/ms, c3 = 0.013/ms, c4 = 1, a = 0.13 — Rogers & McCulloch,
 * IEEE Trans. Biomed. Eng. 41:743-757 (1994), with their time unit taken as 1 ms as the paper's
 * 500 ms cycle implies. Conductivity 3.5 mm^2/ms makes the speed of the bistable front (the
 * recovery variable frozen), c = sqrt(c1 Sigma / 2)(1 - 2a), 0.50 mm/ms; the recovery variable
 * slows the full model's wave below that.
 *
 * Discretisation: P1 elements, consistent mass M and stiffness K (amP1Assembly); first-order
 * semi-implicit (IMEX) Euler: (M + dt K) u^{n+1} = M (u^n + dt f(u^n, v^n)), the reaction explicit,
 * diffusion implicit, then v^{n+1} = (v^n + dt c3 u^{n+1}) / (1 + dt c3 c4). The matrix is
 * assembled and factored once (sparse Cholesky, amSparseCholesky), so each step is two triangular
 * sweeps; Solver CONJUGATE_GRADIENT solves each step by Jacobi-preconditioned conjugate gradients
 * warm-started from the last state instead (amConjugateGradient; no factor in memory). Assembly,
 * products and vector work run on threads; results do not depend on the thread count.
 *
 * Input: a tetrahedral vtkUnstructuredGrid (e.g. Tetrahedralize's output) with cell data
 * RegionArrayName ("Region"). The heart is the cells whose region is in HeartRegions (default 5,
 * the phantom's myocardium); without a region array the whole mesh is the heart. Conductivity
 * per region: RegionConductivities (label, Sigma) pairs, else Conductivity. With a cell vector
 * array FiberArrayName ("Fibers") the tensor is Sigma_l f f^T + Sigma_t (I - f f^T) with
 * Sigma_t = TransverseConductivityRatio * Sigma_l.
 *
 * Stimulus (the sinus-node activation): the heart nodes within StimulusRadius of StimulusCenter,
 * or, when StimulusRegion >= 0, the nodes of that region's cells, or, when EndocardialRegions
 * are given, every heart node on a cell of those regions (the blood pools: the endocardium,
 * standing in for the Purkinje network; activated at once, or spreading from StimulusCenter at
 * EndocardialConductionVelocity), receive I_stim =
 * StimulusStrength (1/ms) from StimulusStart for StimulusDuration ms.
 *
 * Output: the heart sub-mesh (heart cells and their points) with point data "u", "v",
 * "ActivationTime" (ms: when u first crossed ActivationThreshold upwards, linearly interpolated
 * within the step; -1 where that has not happened by the output time) and "InputPointId" (the
 * point's id in the input: TorsoPotential uses it). The output is time-dependent: the filter
 * advertises the times 0, OutputInterval, ..., EndTime, so ParaView animates it and pipelines
 * can request any of them. The whole run is computed once when a time is first requested and the
 * frames are kept (u and v as float) until the input or a property changes; the time asked for
 * is answered with the last frame at or before it.
 *
 * Errors (no output, never NaN): no tetrahedra of the heart regions, a non-tetrahedral or
 * degenerate heart cell, a stimulus that holds no heart node or is shorter than a time step, a
 * time step beyond the explicit reaction's stability limit (2 / max |df/du|), a solver that does
 * not converge, and a non-finite state.
 *
 * References: J. M. Rogers and A. D. McCulloch, A collocation-Galerkin finite element model of
 * cardiac action potential propagation, IEEE TBME 41(8), 1994; the CEMRACS 2004 paper's case study.
 *
 * @sa amTorsoPotential amTetrahedralize
 */
#ifndef amFitzHughNagumoSolver_h
#define amFitzHughNagumoSolver_h

#include "AnatomeshFiltersSimulationModule.h" // export macro
#include "amHeartSolver.h"

#include <memory>
#include <string>
#include <vector>

class amTetraSubset;
class vtkDataArray;

class ANATOMESHFILTERSSIMULATION_EXPORT amFitzHughNagumoSolver : public amHeartSolver
{
public:
  static amFitzHughNagumoSolver* New();
  vtkTypeMacro(amFitzHughNagumoSolver, amHeartSolver);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // From amHeartSolver: HeartRegions (default 5), RegionArrayName ("Region"), FiberArrayName
  // ("Fibers"; unused when absent), StimulusCenter and StimulusRadius (10 mm),
  // EndocardialConductionVelocity (below; default 0), TimeStep (default 0.5 ms), EndTime (500 ms),
  // OutputInterval (default 5 ms; rounded to a whole number of steps), NumberOfHeartNodes and
  // WallSeconds (the time loop's).

  ///@{
  /// Conductivity Sigma (mm^2/ms) where no per-region value is given (default 3.5).
  vtkSetClampMacro(Conductivity, double, 0.0, 1e6);
  vtkGetMacro(Conductivity, double);
  ///@}

  ///@{
  /// Per-region conductivities as (label, Sigma) pairs (mm^2/ms); none by default.
  void AddRegionConductivity(double label, double sigma);
  void RemoveAllRegionConductivities();
  ///@}

  ///@{
  /// The ratio of cross-fiber to along-fiber conductivity (default 0.25).
#ifndef __VTK_WRAP__
  [[deprecated("use SetFiberArrayName")]] void SetFibreArrayName(const char* name)
  {
    this->SetFiberArrayName(name);
  }
  [[deprecated("use GetFiberArrayName")]] const char* GetFibreArrayName()
  {
    return this->GetFiberArrayName();
  }
#endif
  vtkSetClampMacro(TransverseConductivityRatio, double, 0.0, 1.0);
  vtkGetMacro(TransverseConductivityRatio, double);
  ///@}

  ///@{
  /// Rogers-McCulloch parameters: C1, C2, C3 in 1/ms, C4 and the excitation threshold A
  /// dimensionless (defaults 0.26, 0.1, 0.013, 1, 0.13).
  vtkSetClampMacro(C1, double, 0.0, 1e6);
  vtkGetMacro(C1, double);
  vtkSetClampMacro(C2, double, 0.0, 1e6);
  vtkGetMacro(C2, double);
  vtkSetClampMacro(C3, double, 0.0, 1e6);
  vtkGetMacro(C3, double);
  vtkSetClampMacro(C4, double, 0.0, 1e6);
  vtkGetMacro(C4, double);
  vtkSetClampMacro(A, double, 0.0, 0.5);
  vtkGetMacro(A, double);
  ///@}

  ///@{
  /// Optional input 1: landmarks with named points (amCardiacLandmarks' output); its "Stimulus"
  /// point is the stimulus sphere's centre, in place of StimulusCenter.
  void SetLandmarksConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(1, output);
  }

  /// Stimulus: the sphere (StimulusCenter, StimulusRadius) or, when StimulusRegion >= 0, that
  /// region; start (ms, 0), duration (ms, 2), strength (1/ms added to du/dt, 0.5).
  vtkSetMacro(StimulusRegion, int);
  vtkGetMacro(StimulusRegion, int);
  /// Endocardial fast activation: regions (not heart regions; e.g. 6 7, the blood pools) whose
  /// cells' heart nodes are stimulated, instead of the sphere or StimulusRegion (default none).
  /// One layer of nodes drains into the wall faster than a sphere: with elements of 1 mm it
  /// needs StimulusStrength 2.
  void AddEndocardialRegion(int label);
  void RemoveAllEndocardialRegions();
  int GetNumberOfEndocardialRegions()
  {
    return static_cast<int>(this->EndocardialRegions.size());
  }
  /// With EndocardialRegions: how fast (mm/ms) the activation spreads over the endocardium from
  /// StimulusCenter, the Purkinje network's conduction (default 0: the whole endocardium at
  /// once). Each endocardial node's stimulus starts after StimulusStart by its straight-line
  /// distance from StimulusCenter, less the nearest endocardial node's, over this speed: a
  /// stand-in for the network's spread, not its tree (its fibres conduct at 2-4 mm/ms along
  /// longer paths; on the 2 mm phantom heart 1.5 gives an activation of 96 ms, 2 of 85 ms,
  /// against 59 ms at once).
  vtkSetMacro(StimulusStart, double);
  vtkGetMacro(StimulusStart, double);
  vtkSetClampMacro(StimulusDuration, double, 0.0, 1e7);
  vtkGetMacro(StimulusDuration, double);
  vtkSetMacro(StimulusStrength, double);
  vtkGetMacro(StimulusStrength, double);
  ///@}

  ///@{
  /// Threshold on u for the activation time (default 0.5).
  vtkSetClampMacro(ActivationThreshold, double, 0.0, 1.0);
  vtkGetMacro(ActivationThreshold, double);
  ///@}

  ///@{
  /// Linear solver of each step. DIRECT (default): M + dt K factored once (CHOLMOD), each step
  /// two triangular sweeps. CONJUGATE_GRADIENT: Jacobi-preconditioned conjugate gradients,
  /// warm-started, no factor (also where the factor cannot be made).
  enum SolverType
  {
    DIRECT = 0,
    CONJUGATE_GRADIENT = 1
  };
  vtkSetClampMacro(Solver, int, DIRECT, CONJUGATE_GRADIENT);
  vtkGetMacro(Solver, int);
  void SetSolverToDirect()
  {
    this->SetSolver(DIRECT);
  }
  void SetSolverToConjugateGradient()
  {
    this->SetSolver(CONJUGATE_GRADIENT);
  }
  ///@}

  ///@{
  /// Conjugate gradients: relative residual (default 1e-8) and iteration cap (default 1000).
  vtkSetClampMacro(SolverTolerance, double, 1e-16, 0.1);
  vtkGetMacro(SolverTolerance, double);
  vtkSetClampMacro(MaximumIterations, int, 1, 1000000);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /// Figures of the last run (besides NumberOfHeartNodes and WallSeconds): steps, mean CG
  /// iterations per step (0 with the DIRECT solver), fraction of heart nodes activated by the end.
  vtkGetMacro(NumberOfSteps, int);
  vtkGetMacro(MeanIterations, double);
  vtkGetMacro(ActivatedFraction, double);
  ///@}

  /// The largest stable time step for the explicit reaction term with the current parameters.
  double StableTimeStep() const;

protected:
  amFitzHughNagumoSolver();
  ~amFitzHughNagumoSolver() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::vector<int> EndocardialRegions;
  double Conductivity;
  std::vector<double> RegionConductivities; // pairs
  double TransverseConductivityRatio;
  double C1, C2, C3, C4, A;
  double ActiveStimulus[3] = { 0, 0, 0 }; // StimulusCenter, or the Landmarks input's Stimulus
  int StimulusRegion;
  double StimulusStart, StimulusDuration, StimulusStrength;
  double ActivationThreshold;
  int Solver;
  double SolverTolerance;
  int MaximumIterations;

  int NumberOfSteps;
  double MeanIterations;
  double ActivatedFraction;

private:
  amFitzHughNagumoSolver(const amFitzHughNagumoSolver&) = delete;
  void operator=(const amFitzHughNagumoSolver&) = delete;
  struct Run;
  std::unique_ptr<Run> Cache;
  int Simulate(vtkUnstructuredGrid* input);
  /// The heart nodes the stimulus starts (endocardial regions, a stimulus region or the sphere);
  /// where there is none, what it asked for.
  std::string StimulatedNodes(vtkUnstructuredGrid* input, vtkDataArray* regions, const amTetraSubset& subset,
    std::vector<unsigned char>& stimulated) const;
  std::vector<double> FrameTimes() const;
};

#endif
