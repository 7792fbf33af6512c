#include "amFitzHughNagumoSolver.h"

#include "amLandmarkPoints.h"

#include "amConjugateGradient.h"
#include "amFitzHughNagumoStepper.h"
#include "amP1Assembly.h"
#include "amProvenance.h"
#include "amSimulationRun.h"
#include "amSparseMatrix.h"
#include "amTetraSubset.h"
#include "amThreading.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

vtkStandardNewMacro(amFitzHughNagumoSolver);

// Everything one simulation produced: the heart mesh, the frames, the activation times.
struct amFitzHughNagumoSolver::Run
{
  vtkMTimeType InputTime = 0;
  vtkMTimeType FilterTime = 0;
  vtkMTimeType LandmarksTime = 0;
  long long Id = 0;
  vtkSmartPointer<vtkUnstructuredGrid> Heart; // geometry, Region, InputPointId
  std::vector<double> Times;                  // frame times
  std::vector<std::vector<float>> U, V;       // per frame, per heart node
  std::vector<double> Activation;             // per heart node, -1: never
};

amFitzHughNagumoSolver::amFitzHughNagumoSolver()
  : Conductivity(3.5)
  , TransverseConductivityRatio(0.25)
  , C1(0.26)
  , C2(0.1)
  , C3(0.013)
  , C4(1.0)
  , A(0.13)
  , StimulusRegion(-1)
  , StimulusStart(0.0)
  , StimulusDuration(5.0)
  , StimulusStrength(1.0)
  , ActivationThreshold(0.5)
  , Solver(DIRECT)
  , SolverTolerance(1e-8)
  , MaximumIterations(1000)
  , NumberOfSteps(0)
  , MeanIterations(0)
  , ActivatedFraction(0)
{
  amThreading::Initialize();
  this->SetNumberOfInputPorts(2);
  this->TimeStep = 0.5;
  this->OutputInterval = 5.0;
  this->EndocardialConductionVelocity = 0.0;
}

int amFitzHughNagumoSolver::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 1 ? "vtkPolyData" : "vtkUnstructuredGrid");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

amFitzHughNagumoSolver::~amFitzHughNagumoSolver() = default;

void amFitzHughNagumoSolver::AddEndocardialRegion(int label)
{
  this->EndocardialRegions.push_back(label);
  this->Modified();
}

void amFitzHughNagumoSolver::RemoveAllEndocardialRegions()
{
  if (!this->EndocardialRegions.empty())
  {
    this->EndocardialRegions.clear();
    this->Modified();
  }
}

void amFitzHughNagumoSolver::AddRegionConductivity(double label, double sigma)
{
  this->RegionConductivities.push_back(label);
  this->RegionConductivities.push_back(sigma);
  this->Modified();
}

void amFitzHughNagumoSolver::RemoveAllRegionConductivities()
{
  if (!this->RegionConductivities.empty())
  {
    this->RegionConductivities.clear();
    this->Modified();
  }
}

double amFitzHughNagumoSolver::StableTimeStep() const
{
  return amFitzHughNagumoStepper::StableTimeStep(this->C1, this->C2, this->A);
}

std::vector<double> amFitzHughNagumoSolver::FrameTimes() const
{
  const int steps = static_cast<int>(std::llround(this->EndTime / this->TimeStep));
  const int every = std::max(1, static_cast<int>(std::llround(this->OutputInterval / this->TimeStep)));
  std::vector<double> times;
  for (int s = 0; s <= steps; s += every)
    times.push_back(s * this->TimeStep);
  if (steps % every != 0)
    times.push_back(steps * this->TimeStep);
  return times;
}

int amFitzHughNagumoSolver::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const std::vector<double> times = this->FrameTimes();
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  const double range[2] = { times.front(), times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

namespace
{
/// The conductivity tensor of each heart tetrahedron: its region's conductivity (pairs region,
/// S/m; 'sigma' for the others) along its fibre, 'ratio' of it across.
std::vector<std::array<double, 6>> ConductivityTensors(const std::vector<vtkIdType>& heartCells, vtkDataArray* regions,
  vtkDataArray* fibers, const std::vector<double>& regionConductivities, double sigma, double ratio)
{
  std::map<int, double> sigmaOf;
  for (std::size_t k = 0; k + 1 < regionConductivities.size(); k += 2)
    sigmaOf[static_cast<int>(regionConductivities[k])] = regionConductivities[k + 1];
  std::vector<std::array<double, 6>> tensors(heartCells.size());
  for (std::size_t k = 0; k < heartCells.size(); ++k)
  {
    double s = sigma;
    if (regions)
    {
      const auto it = sigmaOf.find(static_cast<int>(regions->GetComponent(heartCells[k], 0)));
      if (it != sigmaOf.end())
        s = it->second;
    }
    double f[3] = { 0, 0, 0 };
    if (fibers)
      fibers->GetTuple(heartCells[k], f);
    tensors[k] = amP1Assembly::FiberTensor(s, s * ratio, f);
  }
  return tensors;
}

/// The Purkinje network's stand-in spreading at a speed: each endocardial node's stimulus starts
/// after StimulusStart by its distance from the stimulus centre, less that of the nearest
/// endocardial node (which starts at StimulusStart), over that speed.
std::vector<double> EndocardialDelays(
  const amP1Assembly& fem, const std::vector<unsigned char>& stimulated, const double centre[3], double speed)
{
  const std::size_t n = fem.Points.size();
  std::vector<double> delays(n, 0.0);
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i)
    if (stimulated[i])
    {
      double d2 = 0;
      for (int c = 0; c < 3; ++c)
        d2 += (fem.Points[i][c] - centre[c]) * (fem.Points[i][c] - centre[c]);
      delays[i] = std::sqrt(d2);
      nearest = std::min(nearest, delays[i]);
    }
  for (std::size_t i = 0; i < n; ++i)
    if (stimulated[i])
      delays[i] = (delays[i] - nearest) / speed;
  return delays;
}
}

std::string amFitzHughNagumoSolver::StimulatedNodes(vtkUnstructuredGrid* input, vtkDataArray* regions,
  const amTetraSubset& subset, std::vector<unsigned char>& stimulated) const
{
  stimulated.assign(subset.Global.size(), 0);
  if (!this->EndocardialRegions.empty())
  {
    // The Purkinje network's stand-in: every heart node on a cell of the given regions (the
    // blood pools) is stimulated at once.
    const std::set<int> endo(this->EndocardialRegions.begin(), this->EndocardialRegions.end());
    for (vtkIdType c = 0; regions && c < input->GetNumberOfCells(); ++c)
      if (endo.count(static_cast<int>(regions->GetComponent(c, 0))))
      {
        const vtkIdType* ids;
        vtkIdType npts;
        input->GetCellPoints(c, npts, ids);
        for (vtkIdType k = 0; k < npts; ++k)
          if (subset.Local[ids[k]] >= 0)
            stimulated[subset.Local[ids[k]]] = 1;
      }
  }
  else if (this->StimulusRegion >= 0)
  {
    for (std::size_t k = 0; k < subset.Cells.size(); ++k)
      if (regions && static_cast<int>(regions->GetComponent(subset.Cells[k], 0)) == this->StimulusRegion)
        for (vtkIdType v : subset.Fem.Tetrahedra[k])
          stimulated[v] = 1;
  }
  else
    for (vtkIdType i : subset.NodesWithin(this->ActiveStimulus, this->StimulusRadius))
      stimulated[i] = 1;
  if (std::find(stimulated.begin(), stimulated.end(), 1) != stimulated.end())
    return "";
  std::ostringstream where;
  if (!this->EndocardialRegions.empty())
    where << "no cell of the endocardial regions touches the heart";
  else if (this->StimulusRegion >= 0)
    where << "region " << this->StimulusRegion << " is not a heart region with cells";
  else
    where << "the sphere of radius " << this->StimulusRadius << " mm around (" << this->ActiveStimulus[0] << ", "
          << this->ActiveStimulus[1] << ", " << this->ActiveStimulus[2] << ") holds no heart node";
  return where.str();
}

int amFitzHughNagumoSolver::Simulate(vtkUnstructuredGrid* input)
{
  auto run = std::make_unique<Run>();
  vtkDataArray* regions = this->RegionArrayName ? input->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  // Heart cells and their nodes, numbered in input order.
  std::vector<vtkIdType> heartCells;
  std::string problem =
    amTetraSubset::SelectRegions(input, regions, this->RegionArrayName, this->HeartRegions, heartCells);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return 0;
  }
  const double dt = this->TimeStep;
  if (dt > this->StableTimeStep())
  {
    vtkErrorMacro(<< "time step " << dt << " ms is too large for stability: the explicit reaction term "
                  << "needs dt <= " << this->StableTimeStep() << " ms with these parameters");
    return 0;
  }
  if (this->StimulusDuration < dt)
  {
    vtkErrorMacro(<< "the stimulus lasts " << this->StimulusDuration << " ms, less than one time step (" << dt
                  << " ms): it would be missed");
    return 0;
  }

  amTetraSubset subset;
  subset.Build(input, heartCells);
  amP1Assembly& fem = subset.Fem;
  const vtkIdType n = static_cast<vtkIdType>(subset.Global.size());
  const vtkIdType bad = fem.FindDegenerate();
  if (bad >= 0)
  {
    vtkErrorMacro(<< "heart tetrahedron " << heartCells[bad]
                  << " is degenerate (flat, collapsed or with a non-finite coordinate)");
    return 0;
  }

  vtkDataArray* fibers = this->FiberArrayName ? input->GetCellData()->GetArray(this->FiberArrayName) : nullptr;
  if (fibers && fibers->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro(<< "fiber array '" << this->FiberArrayName << "' has " << fibers->GetNumberOfComponents()
                  << " components; it needs 3 (a direction per cell)");
    return 0;
  }
  const std::vector<std::array<double, 6>> tensors = ConductivityTensors(
    heartCells, regions, fibers, this->RegionConductivities, this->Conductivity, this->TransverseConductivityRatio);
  std::vector<unsigned char> stimulated;
  problem = this->StimulatedNodes(input, regions, subset, stimulated);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "the stimulus is outside the heart: " << problem);
    return 0;
  }
  this->UpdateProgress(0.02);

  amFitzHughNagumoStepper::Parameters sp;
  sp.C1 = this->C1;
  sp.C2 = this->C2;
  sp.C3 = this->C3;
  sp.C4 = this->C4;
  sp.A = this->A;
  sp.TimeStep = dt;
  sp.ActivationThreshold = this->ActivationThreshold;
  sp.StimulusStart = this->StimulusStart;
  sp.StimulusDuration = this->StimulusDuration;
  sp.StimulusStrength = this->StimulusStrength;
  sp.Direct = this->Solver == DIRECT;
  sp.SolverTolerance = this->SolverTolerance;
  sp.MaximumIterations = this->MaximumIterations;
  // The Purkinje network's stand-in spreading at a speed: each endocardial node's stimulus
  // starts after StimulusStart by its distance from StimulusCenter, less that of the nearest
  // endocardial node (which starts at StimulusStart), over that speed.
  std::vector<double> delays;
  if (!this->EndocardialRegions.empty() && this->EndocardialConductionVelocity > 0)
    delays = EndocardialDelays(fem, stimulated, this->ActiveStimulus, this->EndocardialConductionVelocity);
  amFitzHughNagumoStepper stepper;
  stepper.Setup(fem, tensors, stimulated, sp, delays);
  this->UpdateProgress(0.05);

  const int steps = static_cast<int>(std::llround(this->EndTime / dt));
  const int every = std::max(1, static_cast<int>(std::llround(this->OutputInterval / dt)));
  run->Times = this->FrameTimes();
  const std::vector<double>& u = stepper.U;
  const std::vector<double>& v = stepper.V;
  auto keepFrame = [&]() {
    run->U.emplace_back(u.begin(), u.end());
    run->V.emplace_back(v.begin(), v.end());
  };
  keepFrame();
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s)
  {
    const double t = s * dt;
    if (!stepper.Step(t))
    {
      vtkErrorMacro(<< stepper.Error << ": raise MaximumIterations or SolverTolerance");
      return 0;
    }
    if ((s + 1) % every == 0 || s + 1 == steps)
    {
      double sum = 0;
      for (vtkIdType i = 0; i < n; ++i)
        sum += u[i] + v[i];
      if (!std::isfinite(sum))
      {
        vtkErrorMacro(<< "the state became non-finite by t = " << t + dt << " ms; nothing is written");
        return 0;
      }
      keepFrame();
      this->UpdateProgress(0.05 + 0.95 * (s + 1) / steps);
      if (this->GetAbortExecute())
        return 0;
    }
  }
  run->Activation = stepper.Activation;
  const long long iterations = stepper.Iterations;
  const double c1 = this->C1, c2 = this->C2, c3 = this->C3, c4 = this->C4, a = this->A;
  this->WallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->NumberOfSteps = steps;
  this->MeanIterations = steps > 0 ? static_cast<double>(iterations) / steps : 0.0;
  this->NumberOfHeartNodes = n;
  vtkIdType activated = 0;
  for (double at : run->Activation)
    activated += at >= 0;
  this->ActivatedFraction = static_cast<double>(activated) / n;

  auto heart = subset.MakeGrid(regions); // points, tetrahedra, Region, InputPointId
  run->Heart = heart;
  run->Id = amSimulationRun::Next();

  std::ostringstream params;
  params << "HeartRegions=";
  for (std::size_t k = 0; k < this->HeartRegions.size(); ++k)
    params << (k ? "," : "") << this->HeartRegions[k];
  params << " Conductivity=" << this->Conductivity << " C1=" << c1 << " C2=" << c2 << " C3=" << c3 << " C4=" << c4
         << " A=" << a << " TimeStep=" << dt << " EndTime=" << this->EndTime << " Stimulus=(" << this->ActiveStimulus[0]
         << "," << this->ActiveStimulus[1] << "," << this->ActiveStimulus[2] << ") r=" << this->StimulusRadius
         << " region=" << this->StimulusRegion << " endocardial=" << this->EndocardialRegions.size()
         << " endocardial_velocity=" << this->EndocardialConductionVelocity << " start=" << this->StimulusStart
         << " duration=" << this->StimulusDuration << " strength=" << this->StimulusStrength
         << " Solver=" << (this->Solver == DIRECT ? "direct" : "CG");
  amProvenance::Record(heart, input, "amFitzHughNagumoSolver", params.str());
  this->Cache = std::move(run);
  return 1;
}

int amFitzHughNagumoSolver::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outInfo);
  if (!input)
  {
    vtkErrorMacro(<< "no input mesh");
    return 0;
  }
  vtkPolyData* landmarks = vtkPolyData::GetData(inputVector[1], 0);
  const vtkMTimeType landmarksTime = landmarks ? landmarks->GetMTime() : 0;
  const bool stale = !this->Cache || this->Cache->InputTime != input->GetMTime() ||
    this->Cache->FilterTime != this->GetMTime() || this->Cache->LandmarksTime != landmarksTime;
  if (stale)
  {
    this->Cache.reset();
    // The stimulus: the Landmarks input's "Stimulus" point where it is connected.
    std::copy(this->StimulusCenter, this->StimulusCenter + 3, this->ActiveStimulus);
    if (landmarks)
    {
      std::vector<double> x;
      std::string why;
      if (!amLandmarkPoints::Named(landmarks, { "Stimulus" }, x, why))
      {
        vtkErrorMacro("The stimulus cannot be taken from the Landmarks input: " << why << ".");
        return 0;
      }
      std::copy(x.begin(), x.end(), this->ActiveStimulus);
    }
    if (!this->Simulate(input))
      return 0;
    this->Cache->InputTime = input->GetMTime();
    this->Cache->FilterTime = this->GetMTime();
    this->Cache->LandmarksTime = landmarksTime;
  }
  const Run& run = *this->Cache;

  std::size_t frame = run.Times.size() - 1;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    frame = 0;
    while (frame + 1 < run.Times.size() && run.Times[frame + 1] <= t + 1e-9 * this->TimeStep)
      ++frame;
  }
  const double time = run.Times[frame];
  output->ShallowCopy(run.Heart);
  const vtkIdType n = run.Heart->GetNumberOfPoints();
  vtkNew<vtkFloatArray> u, v;
  u->SetName("u");
  v->SetName("v");
  u->SetNumberOfTuples(n);
  v->SetNumberOfTuples(n);
  std::copy(run.U[frame].begin(), run.U[frame].end(), u->GetPointer(0));
  std::copy(run.V[frame].begin(), run.V[frame].end(), v->GetPointer(0));
  vtkNew<vtkDoubleArray> act;
  act->SetName("ActivationTime");
  act->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double at = run.Activation[i];
    act->SetValue(i, (at >= 0 && at <= time + 1e-9) ? at : -1.0);
  }
  output->GetPointData()->AddArray(u);
  output->GetPointData()->AddArray(v);
  output->GetPointData()->AddArray(act);
  output->GetPointData()->SetActiveScalars("u");
  amSimulationRun::Stamp(output, run.Id);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}

void amFitzHughNagumoSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Conductivity: " << this->Conductivity << "\n";
  os << indent << "C1, C2, C3, C4, A: " << this->C1 << ", " << this->C2 << ", " << this->C3 << ", " << this->C4 << ", "
     << this->A << "\n";
  os << indent << "StimulusRegion: " << this->StimulusRegion << "\n";
  os << indent << "EndocardialRegions: " << this->EndocardialRegions.size() << "\n";
  os << indent << "Solver: " << (this->Solver == DIRECT ? "DIRECT" : "CONJUGATE_GRADIENT")
     << " SolverTolerance: " << this->SolverTolerance << " MaximumIterations: " << this->MaximumIterations << "\n";
}
