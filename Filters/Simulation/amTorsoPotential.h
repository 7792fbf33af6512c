/**
 * @class   amTorsoPotential
 * @brief   Body-surface potentials and a virtual 12-lead ECG: the quasi-static Poisson problem
 *          div(sigma grad phi) = 0 on the torso, with the heart's potential as Dirichlet data.
 *
 * Input 0 ("Mesh"): the whole tetrahedral mesh (cell data RegionArrayName, default "Region").
 * Input 1 ("Heart"): the heart solution, normally amFitzHughNagumoSolver's output: a mesh whose
 * point data "InputPointId" names each heart node's point in input 0 and PotentialArrayName
 * (default "u") holds its potential; the heart's regions are the region labels of its cells.
 *
 * The torso is every tetrahedron of input 0 outside the heart regions (lungs, blood pools, soft
 * tissue, bone, ...), with conductivity per region: RegionConductivities (label, sigma) pairs,
 * else Conductivity. Units cancel (only ratios matter); the defaults are in S/m for the phantom's
 * labels: soft tissue (1) 0.2, fat (2) 0.04, lungs (3, 4) 0.05, blood (6, 7, 8, the atria 11) 0.7,
 * bone (9, 10) 0.02, the airway (12, air-filled as the lungs) 0.05: values of the order used in
 * ECG forward models (blood about 3x muscle, lung about a quarter, fat and bone lower).
 * phi = PotentialScale * (heart potential) on the torso nodes shared with the heart
 * (PotentialScale 100: u = 1 is a 100 mV depolarisation, so phi is in mV above rest), zero flux on
 * the body surface (natural boundary condition). P1 elements (amP1Assembly), the matrix assembled
 * and factored once (sparse Cholesky, amSparseCholesky), or, as an option, Jacobi-preconditioned
 * conjugate gradients warm-started from the previous time (amConjugateGradient). Torso parts that
 * touch no heart node (an undetermined potential) are held at 0 with a warning.
 *
 * Time: when input 1 is time-dependent the filter runs the whole series once (it requests every
 * time step of the heart in turn), keeps the potentials of every step (float), and then answers
 * any requested time without solving again. The direct solver orders the matrix by METIS's nested
 * dissection with its two halves ordered at once (one by a forked child process,
 * amNestedDissection), and solves the steps 64 at a time, half of them on each of two threads (a
 * fixed split: the same bytes on any number of cores). Output 0: the torso mesh (its tetrahedra, Region,
 * point data "Potential" in mV, "InputPointId"), time-dependent like the heart. Output 1: a
 * vtkTable over all times: Time (ms), then the leads I, II, III, aVR, aVL, aVF, V1..V6 (mV; V1-V6
 * against Wilson's central terminal) when 9 electrodes are given (RA, LA, LL, V1..V6), or the
 * potential of each electrode ("E0", "E1", ...) against their mean otherwise. Electrodes:
 * ElectrodePositions (x y z triples, mm), or the points RA, LA, LL, V1..V6 of the optional input 2
 * (Landmarks: amCardiacLandmarks' output, computed on the segmented body), each snapped to the closest body-surface
 * node (the snapped positions are in the table's field data "Electrodes"); the default is the phantom's standard
 * placement (amThoraxPhantomModel::StandardElectrodes). Output 2: the body surface alone (the torso's outer triangles,
 * vtkPolyData with "Potential" and "InputPointId"), time-dependent — the small thing to write as a time series.
 *
 * Errors: missing inputs or arrays, no torso cells, a torso that does not touch the heart, a
 * non-tetrahedral or degenerate torso cell, a matrix that cannot be factored (out of memory),
 * a solver that does not converge.
 *
 * Reference: the CEMRACS 2004 paper's case study (Generation of computational meshes from MRI and
 * CT-scan data): the heart's potential as a Dirichlet condition on the torso's Laplace problem.
 *
 * @sa amFitzHughNagumoSolver
 */
#ifndef amTorsoPotential_h
#define amTorsoPotential_h

#include "AnatomeshFiltersSimulationModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

class ANATOMESHFILTERSSIMULATION_EXPORT amTorsoPotential : public vtkUnstructuredGridAlgorithm
{
public:
  static amTorsoPotential* New();
  vtkTypeMacro(amTorsoPotential, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The heart solution (input 1).
  void SetHeartConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  /// Optional: landmarks with named points (amCardiacLandmarks' output); its RA, LA, LL, V1..V6
  /// are the electrodes, in place of ElectrodePositions.
  void SetLandmarksConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }
  void SetHeartData(vtkDataObject* heart) { this->SetInputData(1, heart); }

  ///@{
  /// Cell array of region labels (default "Region").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  ///@{
  /// Heart point array used as Dirichlet data (default "u") and its scale (default 100: mV).
  vtkSetStringMacro(PotentialArrayName);
  vtkGetStringMacro(PotentialArrayName);
  vtkSetMacro(PotentialScale, double);
  vtkGetMacro(PotentialScale, double);
  ///@}

  ///@{
  /// Conductivity where no per-region value is given (default 0.2) and (label, sigma) pairs.
  vtkSetClampMacro(Conductivity, double, 0.0, 1e6);
  vtkGetMacro(Conductivity, double);
  void AddRegionConductivity(double label, double sigma);
  void RemoveAllRegionConductivities();
  int GetNumberOfRegionConductivities() { return static_cast<int>(this->RegionConductivities.size() / 2); }
  /// The i-th (label, sigma) pair.
  double* GetRegionConductivity(int i) VTK_SIZEHINT(2) { return &this->RegionConductivities.at(2 * i); }
  ///@}

  ///@{
  /// Electrode positions (x y z triples, mm). Nine electrodes give the standard 12 leads.
  void AddElectrode(double x, double y, double z);
  void RemoveAllElectrodes();
  int GetNumberOfElectrodes() { return static_cast<int>(this->ElectrodePositions.size() / 3); }
  /// The i-th electrode's position.
  double* GetElectrode(int i) VTK_SIZEHINT(3) { return &this->ElectrodePositions.at(3 * i); }
  ///@}

  ///@{
  /// How the heart drives the torso. DIRICHLET (default, the paper's): the heart's potential
  /// (PotentialScale x u) is imposed on the torso nodes it shares with the heart, and the torso
  /// alone is solved; the leads are then monophasic, tens of mV. CURRENT_SOURCE: the
  /// transmembrane potential Vm = PotentialScale x u (mV) is a current source in the whole
  /// mesh, div((sigma_i + sigma_e) grad phi) = -div(sigma_i grad Vm), sigma_i =
  /// IntracellularConductivity in the heart's regions (0 elsewhere) and sigma_e the region's
  /// conductivity (RegionConductivities / Conductivity, for the heart too); zero flux on the body
  /// surface, whose mean potential is the reference. Output 0 is then the whole mesh. The
  /// potential of a dipole in a homogeneous sphere checks it (TestTorsoPotential).
  enum CouplingType
  {
    DIRICHLET = 0,
    CURRENT_SOURCE = 1
  };
  vtkSetClampMacro(Coupling, int, DIRICHLET, CURRENT_SOURCE);
  vtkGetMacro(Coupling, int);
  void SetCouplingToDirichlet() { this->SetCoupling(DIRICHLET); }
  void SetCouplingToCurrentSource() { this->SetCoupling(CURRENT_SOURCE); }
  ///@}

  ///@{
  /// The heart's intracellular conductivity for the current-source coupling (default 0.17, S/m
  /// like the region conductivities: a bidomain model's value along the fibres).
  vtkSetClampMacro(IntracellularConductivity, double, 0.0, 1e6);
  vtkGetMacro(IntracellularConductivity, double);
  ///@}

  ///@{
  /// Linear solver. DIRECT (default): the torso matrix is factored once (sparse Cholesky,
  /// CHOLMOD) and every time step costs two triangular sweeps — exact to rounding, and the fast
  /// choice when many steps are solved. CONJUGATE_GRADIENT: Jacobi-preconditioned CG warm-started
  /// from the previous step (no factor to store: the choice when memory is short).
  enum SolverType
  {
    DIRECT = 0,
    CONJUGATE_GRADIENT = 1
  };
  vtkSetClampMacro(Solver, int, DIRECT, CONJUGATE_GRADIENT);
  vtkGetMacro(Solver, int);
  void SetSolverToDirect() { this->SetSolver(DIRECT); }
  void SetSolverToConjugateGradient() { this->SetSolver(CONJUGATE_GRADIENT); }
  ///@}

  ///@{
  /// Conjugate gradients: relative residual (default 1e-6) and iteration cap (default 5000).
  vtkSetClampMacro(SolverTolerance, double, 1e-16, 0.1);
  vtkGetMacro(SolverTolerance, double);
  vtkSetClampMacro(MaximumIterations, int, 1, 1000000);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /// Figures of the last run: torso nodes, Dirichlet (heart) nodes, time steps solved, mean CG
  /// iterations per step, wall seconds of the solves.
  vtkGetMacro(NumberOfTorsoNodes, vtkIdType);
  vtkGetMacro(NumberOfHeartNodes, vtkIdType);
  vtkGetMacro(NumberOfSolves, int);
  vtkGetMacro(MeanIterations, double);
  vtkGetMacro(WallSeconds, double);
  ///@}

  ///@{
  /// Figures of the direct solver's factorisation: seconds, non-zeros of the factor (its memory
  /// is about 12 bytes each).
  vtkGetMacro(FactorSeconds, double);
  vtkGetMacro(FactorNonZeros, double);
  ///@}

protected:
  amTorsoPotential();
  ~amTorsoPotential() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* RegionArrayName;
  char* PotentialArrayName;
  double PotentialScale;
  double Conductivity;
  std::vector<double> RegionConductivities;
  std::vector<double> ElectrodePositions;
  int Coupling;
  double IntracellularConductivity;
  int Solver;
  double SolverTolerance;
  int MaximumIterations;

  vtkIdType NumberOfTorsoNodes;
  vtkIdType NumberOfHeartNodes;
  int NumberOfSolves;
  double MeanIterations;
  double WallSeconds;
  double FactorSeconds;
  double FactorNonZeros;

private:
  amTorsoPotential(const amTorsoPotential&) = delete;
  void operator=(const amTorsoPotential&) = delete;
  struct Model;
  std::unique_ptr<Model> State;
  std::vector<double> ActiveElectrodes; // ElectrodePositions, or the Landmarks input's
  int LoopIndex;                        // -1: not looping over the heart's times
  std::vector<double> LoopTimes;        // the heart's times of the running loop
  bool Prepare(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* heart);
  /// The provenance record's parameters.
  std::string ProvenanceParameters(bool source, std::size_t electrodes) const;
  bool Solve(vtkUnstructuredGrid* heart, double time);
  bool Flush();
  void Produce(vtkInformationVector* outputVector);
};

#endif
