/**
 * @class   amReactionEikonalSolver
 * @brief   A heartbeat on the ventricles: anisotropic eikonal activation from the conduction
 *          system's early sites over a fast endocardium, then a Mitchell-Schaeffer action potential
 *          at every node from its activation time, with transmural and apico-basal duration gradients.
 *
 * Input 0 ("Mesh"): a tetrahedral mesh with cell data RegionArrayName ("Region"), the fibres
 * (FiberArrayName, "Fibers") and point data TransmuralDepth and ApicoBasal (amVentricularFibres'
 * output). Input 1 ("Tags", optional): amVentricularFibres' tagged surface; its LV and RV
 * endocardium is the fast conducting layer (EndocardialConductionVelocity) and holds Durrer's early
 * sites (amEarlySites: the septal endocardium of both ventricles mid-way from apex to base, the RV's
 * RightVentricleDelay ms later). Without it, or with EarlySites = STIMULUS, the activation starts at
 * the heart nodes within StimulusRadius of StimulusCenter (or the Stimulus point of input 2,
 * Landmarks).
 *
 * Activation (amEikonal): sqrt(grad T . D grad T) = 1 with D = v_f^2 f f^T + v_t^2 (I - f f^T),
 * v_f = ConductionVelocityFibre (0.6 mm/ms = m/s), v_t = ConductionVelocityTransverse (0.25), and
 * the endocardial triangles at EndocardialConductionVelocity (2 mm/ms, isotropic in the surface)
 * from the apex up to FastEndocardiumHeight (0.8 of the way to the base: the Purkinje network
 * does not reach the base, which Durrer found activated last).
 * Repolarisation: each node's action potential (amMitchellSchaeffer, amActionPotentialTable) lasts
 *   APD = APD_epi + (APD_endo - APD_epi)(1 - d) + ApicoBasalDurationDifference (h - 1/2)
 *         + ActivationDurationSlope (AT - AT_first),
 * d the transmural depth, h the apico-basal coordinate: the endocardium's 340 ms and the
 * epicardium's 300 ms, the base 30 ms longer than the apex, and -0.7 ms per ms of activation delay
 * (electrotonic coupling: human ventricles show APD falling as activation time rises with a slope
 * near -1, Franz et al. 1987). Around a closed ventricle a uniform transmural gradient's dipoles
 * cancel; the apico-basal and activation-delay terms make the T wave follow the QRS complex. Each
 * node's upstroke is spread over the time the front takes to cross its elements (their mean edge
 * over the geometric mean of the two velocities), the part diffusion plays in a reaction-eikonal
 * model: a coarse mesh gives one smooth QRS complex, not a spike per node.
 *
 * Output: the heart sub-mesh with point data Vm (mV, -85 at rest), ActivationTime (ms),
 * RepolarisationTime (ms, when Vm falls back below 90 % repolarisation), ActionPotentialDuration
 * (ms) and InputPointId; time-dependent (0, OutputInterval, ..., EndTime), every frame computed
 * on request from the activation times and the action potentials (nothing per frame is stored).
 *
 * Errors: no heart cells, a non-tetrahedral heart cell, fibres or depth arrays missing or of the
 * wrong size, no early site or stimulus node, an action potential the model cannot make, and a
 * heart node the activation never reaches (a part of the heart not connected to the sites) is a
 * warning with the count.
 *
 * References: D. Durrer et al., Circulation 41, 1970; M. R. Franz et al., The timing and time course
 * of ventricular repolarization in humans: an inverse relation between activation time and action
 * potential duration, Circulation 75:379-386, 1987; C. C. Mitchell and D. G. Schaeffer, Bull.
 * Math. Biol. 65, 2003; A. Neic et al., Efficient computation of electrograms and ECGs in human
 * whole heart simulations using a reaction-eikonal model, J. Comput. Phys. 346, 2017.
 *
 * @sa amVentricularFibres amLeadFieldECG amFitzHughNagumoSolver
 */
#ifndef amReactionEikonalSolver_h
#define amReactionEikonalSolver_h

#include "AnatomeshFiltersSimulationModule.h" // export macro
#include "amHeartSolver.h"

#include <memory>
#include <vector>

class vtkPolyData;

class ANATOMESHFILTERSSIMULATION_EXPORT amReactionEikonalSolver : public amHeartSolver
{
public:
  static amReactionEikonalSolver* New();
  vtkTypeMacro(amReactionEikonalSolver, amHeartSolver);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Input 1: amVentricularFibres' Tags output; input 2: landmarks (their Stimulus point).
  void SetTagsConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetLandmarksConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }

  // From amHeartSolver: HeartRegions (default 5), RegionArrayName ("Region"), FiberArrayName
  // ("Fibers"), StimulusCenter and StimulusRadius (10 mm), EndocardialConductionVelocity (below;
  // default 2), TimeStep (the cell model's, default 0.05 ms), EndTime (500 ms), OutputInterval
  // (default 1 ms), NumberOfHeartNodes and WallSeconds.

  ///@{
  /// Conduction velocities (mm/ms, which is m/s): along the fibres (default 0.6) and across them
  /// (0.25); over the endocardium EndocardialConductionVelocity (2; 0: no fast layer).
  vtkSetClampMacro(ConductionVelocityFibre, double, 1e-3, 100.0);
  vtkGetMacro(ConductionVelocityFibre, double);
  vtkSetClampMacro(ConductionVelocityTransverse, double, 1e-3, 100.0);
  vtkGetMacro(ConductionVelocityTransverse, double);
  /// How far from the apex the fast endocardium reaches, on the apico-basal coordinate (0 apex, 1
  /// base; default 0.8): the Purkinje network does not reach the base, whose
  /// muscle the front reaches last (Durrer: the posterobasal LV, the basal septum, the RV's outflow).
  vtkSetClampMacro(FastEndocardiumHeight, double, 0.0, 1.0);
  vtkGetMacro(FastEndocardiumHeight, double);
  ///@}

  ///@{
  /// Where activation starts. DURRER (default): the septal endocardium of both ventricles (needs
  /// the Tags input); STIMULUS: the sphere (StimulusCenter, StimulusRadius; or the Landmarks'
  /// Stimulus point).
  enum EarlySitesType
  {
    DURRER = 0,
    STIMULUS = 1
  };
  vtkSetClampMacro(EarlySites, int, DURRER, STIMULUS);
  vtkGetMacro(EarlySites, int);
  /// The RV's septal sites' delay after the LV's (ms, default 5).
  vtkSetClampMacro(RightVentricleDelay, double, 0.0, 1000.0);
  vtkGetMacro(RightVentricleDelay, double);
  ///@}

  ///@{
  /// Action potential durations (ms, APD90) at the endocardium (default 340) and the epicardium
  /// (300), and the base's less the apex's (ms, default 30).
  vtkSetClampMacro(ActionPotentialDurationEndocardium, double, 20.0, 2000.0);
  vtkGetMacro(ActionPotentialDurationEndocardium, double);
  vtkSetClampMacro(ActionPotentialDurationEpicardium, double, 20.0, 2000.0);
  vtkGetMacro(ActionPotentialDurationEpicardium, double);
  vtkSetClampMacro(ApicoBasalDurationDifference, double, -1000.0, 1000.0);
  vtkGetMacro(ApicoBasalDurationDifference, double);
  /// How a cell's duration changes with its activation delay after the first activation (ms per
  /// ms, default -1): electrotonic coupling makes later cells repolarise sooner.
  vtkSetClampMacro(ActivationDurationSlope, double, -2.0, 1.0);
  vtkGetMacro(ActivationDurationSlope, double);
  ///@}

  ///@{
  /// Figures of the last run (besides NumberOfHeartNodes and WallSeconds): the first and last
  /// activation (ms), the last repolarisation (ms).
  vtkGetMacro(FirstActivation, double);
  vtkGetMacro(LastActivation, double);
  vtkGetMacro(LastRepolarisation, double);
  ///@}

protected:
  amReactionEikonalSolver();
  ~amReactionEikonalSolver() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ConductionVelocityFibre, ConductionVelocityTransverse, FastEndocardiumHeight;
  int EarlySites;
  double RightVentricleDelay;
  double ActionPotentialDurationEndocardium, ActionPotentialDurationEpicardium, ApicoBasalDurationDifference;
  double ActivationDurationSlope;
  double FirstActivation, LastActivation, LastRepolarisation;

private:
  amReactionEikonalSolver(const amReactionEikonalSolver&) = delete;
  void operator=(const amReactionEikonalSolver&) = delete;
  struct Run;
  std::unique_ptr<Run> Cache;
  bool Simulate(vtkUnstructuredGrid* input, vtkPolyData* tags, vtkPolyData* landmarks);
  /// Each node's action potential duration (ms) from its transmural depth, apico-basal height and
  /// activation time; the number of nodes never activated.
  vtkIdType Durations(const std::vector<double>& activation, const std::vector<double>& depth,
    const std::vector<double>& apicoBasal, std::vector<double>& duration) const;
  /// Each node's repolarisation time (activation + duration, -1 where never activated), and the
  /// first and last activation and the last repolarisation.
  void Repolarise(Run& run);
  std::vector<double> FrameTimes() const;
};

#endif
