#include "amReactionEikonalSolver.h"

#include "amActionPotentialTable.h"
#include "amEarlySites.h"
#include "amEikonal.h"
#include "amLandmarkPoints.h"
#include "amMitchellSchaeffer.h"
#include "amProvenance.h"
#include "amSimulationRun.h"
#include "amTetraSubset.h"
#include "amVentricularTags.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

vtkStandardNewMacro(amReactionEikonalSolver);

struct amReactionEikonalSolver::Run
{
  long long Id = 0;
  vtkMTimeType InputTime = 0, FilterTime = 0, TagsTime = 0, LandmarksTime = 0;
  vtkSmartPointer<vtkUnstructuredGrid> Heart;
  std::vector<double> Activation, Duration, Repolarisation; // per heart node
  std::vector<double> Spread;                               // per heart node: the upstroke's spread, ms
  amActionPotentialTable Table;
};

amReactionEikonalSolver::amReactionEikonalSolver()
  : ConductionVelocityFibre(0.6)
  , ConductionVelocityTransverse(0.25)
  , FastEndocardiumHeight(0.8)
  , EarlySites(DURRER)
  , RightVentricleDelay(5.0)
  , ActionPotentialDurationEndocardium(340.0)
  , ActionPotentialDurationEpicardium(300.0)
  , ApicoBasalDurationDifference(30.0)
  , ActivationDurationSlope(-0.7)
  , FirstActivation(0)
  , LastActivation(0)
  , LastRepolarisation(0)
{
  this->SetNumberOfInputPorts(3);
  this->EndocardialConductionVelocity = 2.0;
  this->TimeStep = 0.05;
  this->OutputInterval = 1.0;
}

amReactionEikonalSolver::~amReactionEikonalSolver() = default;

int amReactionEikonalSolver::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  if (port > 0)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

std::vector<double> amReactionEikonalSolver::FrameTimes() const
{
  std::vector<double> times;
  const long long frames = std::llround(std::floor(this->EndTime / this->OutputInterval + 1e-9));
  for (long long k = 0; k <= frames; ++k)
    times.push_back(k * this->OutputInterval);
  if (times.back() < this->EndTime - 1e-9)
    times.push_back(this->EndTime);
  return times;
}

int amReactionEikonalSolver::RequestInformation(
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
/// The endocardium's triangles (the Tags input: VentricularTag, InputPointId) added to the eikonal
/// as its fast layer, and its nodes on the LV and the RV side (a node on both counts as LV); the
/// problem, or "".
std::string AddEndocardium(vtkPolyData* tags, const amTetraSubset& subset, double velocity,
  const std::vector<double>& apicoBasal, double top, amEikonal& eikonal, std::vector<vtkIdType>& lv,
  std::vector<vtkIdType>& rv)
{
  vtkDataArray* tag = tags->GetCellData()->GetArray("VentricularTag");
  vtkDataArray* ids = tags->GetPointData()->GetArray("InputPointId");
  if (!tag || !ids)
    return "the Tags input has no cell data VentricularTag or point data InputPointId (Ventricular Fibres' Tags "
           "output has both)";
  const vtkIdType n = static_cast<vtkIdType>(subset.Global.size());
  const vtkIdType nInput = static_cast<vtkIdType>(subset.Local.size());
  std::vector<unsigned char> side(n, 0);
  const double none[3] = { 0, 0, 0 };
  for (vtkIdType c = 0; c < tags->GetNumberOfCells(); ++c)
  {
    const int t = static_cast<int>(tag->GetComponent(c, 0));
    if (t != amVentricularTags::LVEndocardium && t != amVentricularTags::RVEndocardium)
      continue;
    const vtkIdType* pts;
    vtkIdType npts;
    tags->GetCellPoints(c, npts, pts);
    std::array<vtkIdType, 4> tri{ -1, -1, -1, -1 };
    bool inside = npts == 3;
    for (vtkIdType a = 0; a < npts && inside; ++a)
    {
      const vtkIdType global = static_cast<vtkIdType>(ids->GetComponent(pts[a], 0));
      inside = global >= 0 && global < nInput && subset.Local[global] >= 0;
      if (inside)
      {
        tri[a] = subset.Local[global];
        side[tri[a]] |= t == amVentricularTags::LVEndocardium ? 1 : 2;
      }
    }
    if (!inside)
      return "the Tags input does not belong to this mesh: triangle " + std::to_string(c) +
        " has a point that is not a heart node";
    const bool fast = apicoBasal[tri[0]] <= top && apicoBasal[tri[1]] <= top && apicoBasal[tri[2]] <= top;
    if (velocity > 0 && fast)
      eikonal.AddElement(tri, none, velocity, velocity);
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (side[i] & 1)
      lv.push_back(i);
    else if (side[i] & 2)
      rv.push_back(i);
  }
  return "";
}

/// Each node's upstroke spread: the time the front takes to cross its elements (their mean edge
/// length over the speed, mm/ms).
std::vector<double> UpstrokeSpread(const amP1Assembly& fem, double speed)
{
  const std::size_t n = fem.Points.size();
  std::vector<double> spread(n, 0.0), count(n, 0.0);
  for (const auto& t : fem.Tetrahedra)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
      {
        const auto& p = fem.Points[t[a]];
        const auto& q = fem.Points[t[b]];
        const double l =
          std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
        for (vtkIdType v : { t[a], t[b] })
        {
          spread[v] += l;
          count[v] += 1;
        }
      }
  for (std::size_t i = 0; i < n; ++i)
    spread[i] = count[i] > 0 ? spread[i] / count[i] / speed : 0.0;
  return spread;
}
}

vtkIdType amReactionEikonalSolver::Durations(const std::vector<double>& activation, const std::vector<double>& depth,
  const std::vector<double>& apicoBasal, std::vector<double>& duration) const
{
  const std::size_t n = activation.size();
  duration.resize(n);
  vtkIdType unreached = 0;
  double first = std::numeric_limits<double>::infinity();
  for (double a : activation)
    first = std::min(first, a);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double depthHere = std::min(1.0, std::max(0.0, depth[i]));
    const double height = std::min(1.0, std::max(0.0, apicoBasal[i]));
    duration[i] = this->ActionPotentialDurationEpicardium +
      (this->ActionPotentialDurationEndocardium - this->ActionPotentialDurationEpicardium) * (1 - depthHere) +
      this->ApicoBasalDurationDifference * (height - 0.5);
    if (!std::isfinite(activation[i]))
      ++unreached;
    else
      duration[i] += this->ActivationDurationSlope * (activation[i] - first);
  }
  return unreached;
}

void amReactionEikonalSolver::Repolarise(Run& run)
{
  const std::size_t n = run.Activation.size();
  run.Repolarisation.resize(n);
  this->FirstActivation = std::numeric_limits<double>::infinity();
  this->LastActivation = 0;
  this->LastRepolarisation = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double at = run.Activation[i];
    run.Repolarisation[i] = std::isfinite(at) ? at + run.Duration[i] : -1.0;
    if (std::isfinite(at))
    {
      this->FirstActivation = std::min(this->FirstActivation, at);
      this->LastActivation = std::max(this->LastActivation, at);
      this->LastRepolarisation = std::max(this->LastRepolarisation, run.Repolarisation[i]);
    }
  }
}

bool amReactionEikonalSolver::Simulate(vtkUnstructuredGrid* input, vtkPolyData* tags, vtkPolyData* landmarks)
{
  const auto start = std::chrono::steady_clock::now();
  auto run = std::make_unique<Run>();
  vtkDataArray* regions = this->RegionArrayName ? input->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  vtkDataArray* fibres = this->FiberArrayName ? input->GetCellData()->GetArray(this->FiberArrayName) : nullptr;
  vtkDataArray* depth = input->GetPointData()->GetArray("TransmuralDepth");
  vtkDataArray* apicoBasal = input->GetPointData()->GetArray("ApicoBasal");
  if (!regions || !fibres || fibres->GetNumberOfComponents() != 3 || !depth || !apicoBasal)
  {
    vtkErrorMacro(<< "the mesh needs cell data '" << (this->RegionArrayName ? this->RegionArrayName : "") << "' and '"
                  << (this->FiberArrayName ? this->FiberArrayName : "")
                  << "' (3 components) and point data TransmuralDepth and ApicoBasal: run Ventricular Fibres first");
    return false;
  }
  std::vector<vtkIdType> heartCells;
  std::string problem =
    amTetraSubset::SelectRegions(input, regions, this->RegionArrayName, this->HeartRegions, heartCells);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return false;
  }
  amTetraSubset subset;
  subset.Build(input, heartCells);
  const vtkIdType n = static_cast<vtkIdType>(subset.Global.size());
  this->NumberOfHeartNodes = n;

  // The eikonal: the myocardium's tetrahedra, and the endocardium's triangles as the fast layer.
  amEikonal eikonal;
  eikonal.Points = subset.Fem.Points;
  for (std::size_t k = 0; k < heartCells.size(); ++k)
  {
    double f[3];
    fibres->GetTuple(heartCells[k], f);
    const auto& t = subset.Fem.Tetrahedra[k];
    eikonal.AddElement(
      { t[0], t[1], t[2], t[3] }, f, this->ConductionVelocityFibre, this->ConductionVelocityTransverse);
  }
  std::vector<double> ab(n), d(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ab[i] = apicoBasal->GetComponent(subset.Global[i], 0);
    d[i] = depth->GetComponent(subset.Global[i], 0);
  }
  std::vector<vtkIdType> lv, rv;
  if (tags)
  {
    problem = AddEndocardium(
      tags, subset, this->EndocardialConductionVelocity, ab, this->FastEndocardiumHeight, eikonal, lv, rv);
    if (!problem.empty())
    {
      vtkErrorMacro(<< problem);
      return false;
    }
  }
  std::vector<std::pair<vtkIdType, double>> sources;
  std::string sitesFrom;
  if (this->EarlySites == DURRER)
  {
    if (lv.empty())
    {
      vtkErrorMacro(<< "Durrer's early sites need the LV endocardium: connect Ventricular Fibres' Tags output, or set "
                       "EarlySites to Stimulus");
      return false;
    }
    amEarlySites early;
    early.RightDelay = this->RightVentricleDelay;
    sources = early.Find(subset.Fem.Points, lv, rv, ab);
    sitesFrom = "Durrer";
  }
  else
  {
    double centre[3] = { this->StimulusCenter[0], this->StimulusCenter[1], this->StimulusCenter[2] };
    if (landmarks)
    {
      std::vector<double> x;
      std::string why;
      if (!amLandmarkPoints::Named(landmarks, { "Stimulus" }, x, why))
      {
        vtkErrorMacro("The stimulus cannot be taken from the Landmarks input: " << why << ".");
        return false;
      }
      std::copy(x.begin(), x.end(), centre);
    }
    for (vtkIdType i : subset.NodesWithin(centre, this->StimulusRadius))
      sources.push_back({ i, 0.0 });
    std::ostringstream where;
    where << "sphere (" << centre[0] << "," << centre[1] << "," << centre[2] << ") r=" << this->StimulusRadius;
    sitesFrom = where.str();
  }
  if (sources.empty())
  {
    vtkErrorMacro(<< "no early site: "
                  << (this->EarlySites != DURRER ? "the stimulus sphere holds no heart node"
                         : rv.empty() ? "Durrer's septal sites face the RV, and the Tags hold no RV endocardium (no RV "
                                        "blood pool in the mesh: set EarlySites to Stimulus for a heart without one)"
                                      : "no septal endocardium mid-way from apex to base"));
    return false;
  }
  this->UpdateProgress(0.1);
  run->Activation = eikonal.Solve(sources);
  this->UpdateProgress(0.6);

  // Durations per node, and the action potentials they need.
  const vtkIdType unreached = this->Durations(run->Activation, d, ab, run->Duration);
  if (unreached > 0)
    vtkWarningMacro(<< unreached << " of " << n
                    << " heart nodes are never activated: their part of the heart does not touch the early sites");
  amMitchellSchaeffer model;
  run->Table.TimeStep = this->TimeStep;
  if (model.StableTimeStep() < this->TimeStep)
  {
    vtkErrorMacro(<< "time step " << this->TimeStep << " ms is too large for the " << model.Name()
                  << " model: it needs dt <= " << model.StableTimeStep() << " ms");
    return false;
  }
  if (!run->Table.Build(model, run->Duration, this->EndTime))
  {
    vtkErrorMacro(<< run->Table.Error << ": change the action potential durations");
    return false;
  }
  // Repolarisation: the table's own APD90 is the duration asked for (to its resolution).
  this->Repolarise(*run);
  // Each node's upstroke spreads over the time the front takes to cross its elements (their mean
  // edge length over the geometric mean of the velocities): on a coarse mesh the QRS is then one
  // smooth complex, not a spike per node (what diffusion does in a reaction-eikonal model).
  run->Spread =
    UpstrokeSpread(subset.Fem, std::sqrt(this->ConductionVelocityFibre * this->ConductionVelocityTransverse));
  run->Heart = subset.MakeGrid(regions);
  run->Id = amSimulationRun::Next();
  std::ostringstream params;
  params << "CV=" << this->ConductionVelocityFibre << "/" << this->ConductionVelocityTransverse
         << " endocardium=" << this->EndocardialConductionVelocity << " up to " << this->FastEndocardiumHeight
         << " sites=" << sitesFrom << " RVdelay=" << this->RightVentricleDelay
         << " APD=" << this->ActionPotentialDurationEndocardium << "/" << this->ActionPotentialDurationEpicardium
         << " apicobasal=" << this->ApicoBasalDurationDifference << " model=" << model.Name()
         << " dt=" << this->TimeStep << " EndTime=" << this->EndTime;
  amProvenance::Record(run->Heart, input, "amReactionEikonalSolver", params.str());
  this->Cache = std::move(run);
  this->WallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

int amReactionEikonalSolver::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkPolyData* tags = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* landmarks = vtkPolyData::GetData(inputVector[2], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outInfo);
  if (!input)
  {
    vtkErrorMacro(<< "no input mesh");
    return 0;
  }
  const vtkMTimeType tagsTime = tags ? tags->GetMTime() : 0, landmarksTime = landmarks ? landmarks->GetMTime() : 0;
  if (!this->Cache || this->Cache->InputTime != input->GetMTime() || this->Cache->FilterTime != this->GetMTime() ||
    this->Cache->TagsTime != tagsTime || this->Cache->LandmarksTime != landmarksTime)
  {
    this->Cache.reset();
    if (!this->Simulate(input, tags, landmarks))
      return 0;
    this->Cache->InputTime = input->GetMTime();
    this->Cache->FilterTime = this->GetMTime();
    this->Cache->TagsTime = tagsTime;
    this->Cache->LandmarksTime = landmarksTime;
  }
  const Run& run = *this->Cache;
  double time = this->EndTime;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    time = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  output->ShallowCopy(run.Heart);
  const vtkIdType n = run.Heart->GetNumberOfPoints();
  vtkNew<vtkFloatArray> vm, at, rt, apd;
  vm->SetName("Vm");
  at->SetName("ActivationTime");
  rt->SetName("RepolarisationTime");
  apd->SetName("ActionPotentialDuration");
  for (auto* a : { vm.GetPointer(), at.GetPointer(), rt.GetPointer(), apd.GetPointer() })
    a->SetNumberOfTuples(n);
  vtkSMPTools::For(0, n, [&](vtkIdType i0, vtkIdType i1) {
    for (vtkIdType i = i0; i < i1; ++i)
    {
      const double a = run.Activation[i];
      vm->SetValue(i,
        static_cast<float>(run.Table.Voltage(
          run.Duration[i], std::isfinite(a) ? time - a : -std::numeric_limits<double>::infinity(), run.Spread[i])));
      at->SetValue(i, std::isfinite(a) ? static_cast<float>(a) : -1.0f);
      rt->SetValue(i, static_cast<float>(run.Repolarisation[i]));
      apd->SetValue(i, static_cast<float>(run.Duration[i]));
    }
  });
  output->GetPointData()->AddArray(vm);
  output->GetPointData()->AddArray(at);
  output->GetPointData()->AddArray(rt);
  output->GetPointData()->AddArray(apd);
  output->GetPointData()->SetActiveScalars("Vm");
  amSimulationRun::Stamp(output, run.Id);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}

void amReactionEikonalSolver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ConductionVelocity: " << this->ConductionVelocityFibre << " / " << this->ConductionVelocityTransverse
     << " endocardium " << this->EndocardialConductionVelocity << " up to " << this->FastEndocardiumHeight << "\n";
  os << indent << "EarlySites: " << (this->EarlySites == DURRER ? "DURRER" : "STIMULUS") << "\n";
  os << indent << "ActionPotentialDuration: endo " << this->ActionPotentialDurationEndocardium << " epi "
     << this->ActionPotentialDurationEpicardium << " apico-basal " << this->ApicoBasalDurationDifference << "\n";
}
