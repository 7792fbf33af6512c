/**
 * @class   amHeartSolver
 * @brief   What the heart models share: the heart's regions in a labelled tetrahedral mesh, its
 *          fibres, the stimulus sphere, the endocardium's fast conduction and the time axis, and the
 *          figures of the last run.
 *
 * amFitzHughNagumoSolver (the paper's model) and amReactionEikonalSolver (the heartbeat) derive
 * from it; each sets its own defaults for the time axis and the endocardial conduction (given in
 * its header). The heart is the cells whose RegionArrayName label is among HeartRegions; the
 * heart's nodes are numbered in input point order (amTetraSubset).
 *
 * @sa amFitzHughNagumoSolver amReactionEikonalSolver
 */
#ifndef amHeartSolver_h
#define amHeartSolver_h

#include "AnatomeshFiltersSimulationModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <vector>

class ANATOMESHFILTERSSIMULATION_EXPORT amHeartSolver : public vtkUnstructuredGridAlgorithm
{
public:
  vtkTypeMacro(amHeartSolver, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Regions that make up the heart muscle (default: 5, the phantom's myocardium).
  void AddHeartRegion(int label);
  void RemoveAllHeartRegions();
  int GetNumberOfHeartRegions() { return static_cast<int>(this->HeartRegions.size()); }
  int GetHeartRegion(int i) { return this->HeartRegions.at(i); }
  ///@}

  ///@{
  /// Cell arrays of region labels (default "Region") and fibre directions (default "Fibers").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  vtkSetStringMacro(FiberArrayName);
  vtkGetStringMacro(FiberArrayName);
  ///@}

  ///@{
  /// The stimulus sphere: its centre (mm, default the origin; a Landmarks input's Stimulus point
  /// takes its place) and radius (mm, default 10).
  vtkSetVector3Macro(StimulusCenter, double);
  vtkGetVector3Macro(StimulusCenter, double);
  vtkSetClampMacro(StimulusRadius, double, 0.0, 1e6);
  vtkGetMacro(StimulusRadius, double);
  ///@}

  ///@{
  /// How fast activation spreads over the endocardium (mm/ms, which is m/s): the conduction
  /// system's stand-in (each subclass says how it uses it, and its default).
  vtkSetClampMacro(EndocardialConductionVelocity, double, 0.0, 1e6);
  vtkGetMacro(EndocardialConductionVelocity, double);
  ///@}

  ///@{
  /// The time step (ms), the simulated time (ms, default 500) and the time between output frames
  /// (ms); the subclasses give the step's and the frames' defaults.
  vtkSetClampMacro(TimeStep, double, 1e-6, 1e6);
  vtkGetMacro(TimeStep, double);
  vtkSetClampMacro(EndTime, double, 0.0, 1e7);
  vtkGetMacro(EndTime, double);
  vtkSetClampMacro(OutputInterval, double, 1e-6, 1e7);
  vtkGetMacro(OutputInterval, double);
  ///@}

  ///@{
  /// Figures of the last run: the heart's nodes and the wall seconds it took.
  vtkGetMacro(NumberOfHeartNodes, vtkIdType);
  vtkGetMacro(WallSeconds, double);
  ///@}

protected:
  amHeartSolver();
  ~amHeartSolver() override;

  std::vector<int> HeartRegions;
  char* RegionArrayName;
  char* FiberArrayName;
  double StimulusCenter[3];
  double StimulusRadius;
  double EndocardialConductionVelocity;
  double TimeStep;
  double EndTime;
  double OutputInterval;
  vtkIdType NumberOfHeartNodes;
  double WallSeconds;

private:
  amHeartSolver(const amHeartSolver&) = delete;
  void operator=(const amHeartSolver&) = delete;
};

#endif
