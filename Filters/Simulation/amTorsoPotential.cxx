#include "amTorsoPotential.h"

#include "amLandmarkPoints.h"
#include "amLeadFields.h"
#include "amUnits.h"

#include "amConjugateGradient.h"
#include "amP1Assembly.h"
#include "amProvenance.h"
#include "amSimulationRun.h"
#include "amSparseCholesky.h"
#include "amSparseMatrix.h"
#include "amTetraFaces.h"
#include "amTetraSubset.h"
#include "amThoraxPhantomModel.h"
#include "amThreading.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

vtkStandardNewMacro(amTorsoPotential);

// The assembled torso problem and every solved time.
struct amTorsoPotential::Model
{
  vtkMTimeType MeshTime = 0;
  vtkMTimeType FilterTime = 0;
  vtkMTimeType LandmarksTime = 0;
  long long HeartRun = -1;
  vtkSmartPointer<vtkUnstructuredGrid> Torso; // geometry, Region, InputPointId
  vtkSmartPointer<vtkPolyData> Body;          // body-surface triangles
  std::vector<vtkIdType> BodyNodes;           // torso node of each body-surface point
  amSparseMatrix K;
  std::vector<unsigned char> Fixed;
  std::vector<vtkIdType> HeartIndex; // per torso node: point of the heart input, or -1
  amConjugateGradient CG;
  amSparseCholesky Cholesky;
  std::vector<double> X, Zero;
  // Current-source coupling: the intracellular stiffness over the heart, the right-hand side
  // -Ki Vm of each step (batched like X for the direct solver), the body-surface nodes whose mean
  // potential is the reference.
  bool Source = false;
  amSparseMatrix Ki;
  std::vector<double> Vm, Rhs, PendingRhs;
  std::vector<vtkIdType> Electrodes; // torso nodes
  std::vector<std::array<double, 3>> ElectrodePoints;
  std::vector<double> Times;
  std::vector<std::vector<float>> Phi;
  std::vector<std::vector<double>> Leads; // per time: electrode potentials
  long long Iterations = 0;
  double Seconds = 0;
  // Direct solver: time steps whose Dirichlet data wait to be solved together (one pass over
  // the factor for a batch), each a full vector (column-major), and their times.
  std::vector<double> Pending;
  std::vector<double> PendingTimes;
  static constexpr int Batch = 64;
  void Record(double time, const double* x)
  {
    this->Times.push_back(time);
    this->Phi.emplace_back(x, x + this->X.size());
    if (this->Source && !this->BodyNodes.empty())
    {
      // Potentials are defined up to a constant: the body surface's mean is zero.
      double mean = 0.0;
      for (vtkIdType b : this->BodyNodes)
        mean += x[b];
      mean /= static_cast<double>(this->BodyNodes.size());
      for (auto& v : this->Phi.back())
        v = static_cast<float>(v - mean);
    }
    std::vector<double> row;
    for (vtkIdType e : this->Electrodes)
      row.push_back(this->Phi.back()[e]);
    this->Leads.push_back(row);
  }
};

namespace
{

int Find(std::vector<vtkIdType>& parent, vtkIdType i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return static_cast<int>(i);
}
}

amTorsoPotential::amTorsoPotential()
  : RegionArrayName(nullptr)
  , PotentialArrayName(nullptr)
  , PotentialScale(100.0)
  , Conductivity(0.2)
  , RegionConductivities{ 1, 0.2, 2, 0.04, 3, 0.05, 4, 0.05, 6, 0.7, 7, 0.7, 8, 0.7, 9, 0.02, 10, 0.02, 11, 0.7, 12,
    0.05 }
  , Coupling(DIRICHLET)
  , IntracellularConductivity(0.17)
  , Solver(DIRECT)
  , SolverTolerance(1e-6)
  , MaximumIterations(5000)
  , NumberOfTorsoNodes(0)
  , NumberOfHeartNodes(0)
  , NumberOfSolves(0)
  , MeanIterations(0)
  , WallSeconds(0)
  , FactorSeconds(0)
  , FactorNonZeros(0)
  , LoopIndex(-1)
{
  amThreading::Initialize();
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(3);
  this->SetRegionArrayName("Region");
  this->SetPotentialArrayName("u");
  double electrodes[9][3];
  amThoraxPhantomModel::StandardElectrodes(electrodes);
  for (const auto& e : electrodes)
    this->ElectrodePositions.insert(this->ElectrodePositions.end(), e, e + 3);
}

amTorsoPotential::~amTorsoPotential()
{
  this->SetRegionArrayName(nullptr);
  this->SetPotentialArrayName(nullptr);
}

void amTorsoPotential::AddRegionConductivity(double label, double sigma)
{
  this->RegionConductivities.push_back(label);
  this->RegionConductivities.push_back(sigma);
  this->Modified();
}

void amTorsoPotential::RemoveAllRegionConductivities()
{
  if (!this->RegionConductivities.empty())
  {
    this->RegionConductivities.clear();
    this->Modified();
  }
}

void amTorsoPotential::AddElectrode(double x, double y, double z)
{
  this->ElectrodePositions.insert(this->ElectrodePositions.end(), { x, y, z });
  this->Modified();
}

void amTorsoPotential::RemoveAllElectrodes()
{
  if (!this->ElectrodePositions.empty())
  {
    this->ElectrodePositions.clear();
    this->Modified();
  }
}

int amTorsoPotential::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 2 ? "vtkPolyData" : "vtkUnstructuredGrid");
  if (port == 2)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int amTorsoPotential::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(
    vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : (port == 1 ? "vtkTable" : "vtkPolyData"));
  return 1;
}

int amTorsoPotential::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* heartInfo = inputVector[1]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (heartInfo && heartInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    outInfo->CopyEntry(heartInfo, vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    outInfo->CopyEntry(heartInfo, vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  else
  {
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  vtkInformation* bodyInfo = outputVector->GetInformationObject(2);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    bodyInfo->CopyEntry(outInfo, vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    bodyInfo->CopyEntry(outInfo, vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  else
  {
    bodyInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    bodyInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  vtkInformation* tableInfo = outputVector->GetInformationObject(1);
  tableInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  tableInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  return 1;
}

int amTorsoPotential::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* heartInfo = inputVector[1]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (!heartInfo)
    return 1;
  if (this->LoopIndex >= 0)
    heartInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), this->LoopTimes[this->LoopIndex]);
  else if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    heartInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(),
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
  else if (outputVector->GetInformationObject(2)->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    heartInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(),
      outputVector->GetInformationObject(2)->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
  else
    heartInfo->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  return 1;
}

namespace
{
/// Dirichlet coupling: the torso is the cells outside the heart's regions; current source: every
/// cell. Each checked to be a tetrahedron; the problem, or "".
std::string SelectTorso(vtkUnstructuredGrid* mesh, vtkDataArray* regions, const std::set<int>& heartSet, bool source,
  std::vector<vtkIdType>& torsoCells, std::vector<char>& inHeart)
{
  vtkIdType outside = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const bool heartCell = heartSet.count(static_cast<int>(regions->GetComponent(c, 0))) > 0;
    outside += !heartCell;
    if (heartCell && !source)
      continue;
    if (mesh->GetCellType(c) != VTK_TETRA)
      return "torso cell " + std::to_string(c) + " is not a tetrahedron (VTK cell type " +
        std::to_string(mesh->GetCellType(c)) + ")";
    torsoCells.push_back(c);
    inHeart.push_back(heartCell);
  }
  return outside == 0 ? "no torso: every cell of the mesh is in the heart's regions" : "";
}

/// Torso parts without a heart node have no defined potential: they are held at 0 (the number of
/// such nodes is returned). Current source: one heart node of each other part is the reference.
vtkIdType Ground(
  const amP1Assembly& fem, const std::vector<vtkIdType>& heartIndex, bool source, std::vector<unsigned char>& fixed)
{
  const vtkIdType n = static_cast<vtkIdType>(fem.Points.size());
  std::vector<vtkIdType> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& t : fem.Tetrahedra)
    for (int a = 1; a < 4; ++a)
    {
      const int r0 = Find(parent, t[0]), ra = Find(parent, t[a]);
      if (r0 != ra)
        parent[std::max(r0, ra)] = std::min(r0, ra);
    }
  std::vector<unsigned char> grounded(n, 0);
  for (vtkIdType i = 0; i < n; ++i)
    if (fixed[i] || (source && heartIndex[i] >= 0 && !grounded[Find(parent, i)]))
    {
      fixed[i] = 1;
      grounded[Find(parent, i)] = 1;
    }
  vtkIdType floating = 0;
  for (vtkIdType i = 0; i < n; ++i)
    if (!grounded[Find(parent, i)])
    {
      fixed[i] = 1;
      ++floating;
    }
  return floating;
}

/// Each torso tetrahedron's (isotropic) bulk conductivity, S/m: its region's, and in the heart the
/// extracellular plus the intracellular; and the intracellular one alone (0 outside the heart).
void TorsoTensors(vtkDataArray* regions, const std::vector<vtkIdType>& torsoCells, const std::vector<char>& inHeart,
  const std::vector<double>& regionConductivities, double conductivity, double intracellular,
  std::vector<std::array<double, 6>>& tensors, std::vector<std::array<double, 6>>& intra)
{
  std::map<int, double> sigmaOf;
  for (std::size_t k = 0; k + 1 < regionConductivities.size(); k += 2)
    sigmaOf[static_cast<int>(regionConductivities[k])] = regionConductivities[k + 1];
  tensors.resize(torsoCells.size());
  intra.resize(torsoCells.size());
  for (std::size_t k = 0; k < torsoCells.size(); ++k)
  {
    const auto it = sigmaOf.find(static_cast<int>(regions->GetComponent(torsoCells[k], 0)));
    double sigma = it != sigmaOf.end() ? it->second : conductivity;
    const double si = inHeart[k] ? intracellular : 0.0;
    sigma += si;
    tensors[k] = { sigma, sigma, sigma, 0, 0, 0 };
    intra[k] = { si, si, si, 0, 0, 0 };
  }
}

/// The body surface: the faces of exactly one torso tetrahedron (oriented outwards) not all of
/// whose nodes are heart nodes, with point data InputPointId; the torso node of each of its points,
/// and which torso nodes lie on it.
vtkSmartPointer<vtkPolyData> BodySurface(const amTetraSubset& subset, const std::vector<vtkIdType>& heartIndex,
  std::vector<vtkIdType>& bodyNodes, std::vector<unsigned char>& onSurface)
{
  const amP1Assembly& fem = subset.Fem;
  const std::size_t n = fem.Points.size();
  onSurface.assign(n, 0);
  std::vector<vtkIdType> bodyIndex(n, -1);
  auto body = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> bodyPoints;
  bodyPoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  for (const auto& f : amTetraFaces::Find(fem.Points[0].data(), fem.Tetrahedra, nullptr))
  {
    const auto& v = f.Points;
    if (heartIndex[v[0]] >= 0 && heartIndex[v[1]] >= 0 && heartIndex[v[2]] >= 0)
      continue;
    for (vtkIdType p : v)
      onSurface[p] = 1;
    vtkIdType tri[3] = { v[0], v[1], v[2] };
    for (vtkIdType& w : tri)
    {
      if (bodyIndex[w] < 0)
      {
        bodyIndex[w] = static_cast<vtkIdType>(bodyNodes.size());
        bodyNodes.push_back(w);
        bodyPoints->InsertNextPoint(fem.Points[w].data());
      }
      w = bodyIndex[w];
    }
    triangles->InsertNextCell(3, tri);
  }
  body->SetPoints(bodyPoints);
  body->SetPolys(triangles);
  vtkNew<vtkIdTypeArray> bodyIds;
  bodyIds->SetName("InputPointId");
  for (vtkIdType w : bodyNodes)
    bodyIds->InsertNextValue(subset.Global[w]);
  body->GetPointData()->AddArray(bodyIds);
  return body;
}
}

std::string amTorsoPotential::ProvenanceParameters(bool source, std::size_t electrodes) const
{
  std::ostringstream params;
  params << "Conductivity=" << this->Conductivity << " RegionConductivities=";
  for (std::size_t k = 0; k < this->RegionConductivities.size(); ++k)
    params << (k ? "," : "") << this->RegionConductivities[k];
  params << " PotentialArray=" << (this->PotentialArrayName ? this->PotentialArrayName : "")
         << " PotentialScale=" << this->PotentialScale << " Electrodes=" << electrodes
         << " Solver=" << (this->Solver == DIRECT ? "direct" : "CG")
         << " Coupling=" << (source ? "current source" : "Dirichlet");
  if (source)
    params << " IntracellularConductivity=" << this->IntracellularConductivity;
  return params.str();
}

bool amTorsoPotential::Prepare(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* heart)
{
  auto model = std::make_unique<Model>();
  const char* regionName = this->RegionArrayName ? this->RegionArrayName : "";
  vtkDataArray* regions = mesh->GetCellData()->GetArray(regionName);
  vtkDataArray* heartRegions = heart->GetCellData()->GetArray(regionName);
  if (!regions || !heartRegions)
  {
    vtkErrorMacro(<< "the " << (!regions ? "mesh" : "heart") << " input has no cell array '" << regionName
                  << "': the torso is the mesh's cells outside the heart's regions");
    return false;
  }
  vtkDataArray* ids = heart->GetPointData()->GetArray("InputPointId");
  vtkDataArray* potential = heart->GetPointData()->GetArray(this->PotentialArrayName ? this->PotentialArrayName : "");
  if (!ids || !potential)
  {
    vtkErrorMacro(<< "the heart input has no point array '"
                  << (!ids ? "InputPointId" : (this->PotentialArrayName ? this->PotentialArrayName : ""))
                  << "' (connect the output of FitzHughNagumoSolver)");
    return false;
  }
  std::set<int> heartSet;
  for (vtkIdType c = 0; c < heartRegions->GetNumberOfTuples(); ++c)
    heartSet.insert(static_cast<int>(heartRegions->GetComponent(c, 0)));

  // Dirichlet coupling: the torso is the cells outside the heart. Current source: every cell.
  model->Source = this->Coupling == CURRENT_SOURCE;
  std::vector<vtkIdType> torsoCells;
  std::vector<char> inHeart;
  const std::string problem = SelectTorso(mesh, regions, heartSet, model->Source, torsoCells, inHeart);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return false;
  }

  const vtkIdType nMesh = mesh->GetNumberOfPoints();
  amTetraSubset subset;
  subset.Build(mesh, torsoCells);
  amP1Assembly& fem = subset.Fem;
  const std::vector<vtkIdType>& local = subset.Local;
  const vtkIdType n = static_cast<vtkIdType>(subset.Global.size());
  const vtkIdType bad = fem.FindDegenerate();
  if (bad >= 0)
  {
    vtkErrorMacro(<< "torso tetrahedron " << torsoCells[bad]
                  << " is degenerate (flat, collapsed or with a non-finite coordinate)");
    return false;
  }

  // Dirichlet nodes: torso nodes that are heart nodes.
  model->HeartIndex.assign(n, -1);
  model->Fixed.assign(n, 0);
  vtkIdType nFixed = 0;
  for (vtkIdType h = 0; h < ids->GetNumberOfTuples(); ++h)
  {
    const vtkIdType p = static_cast<vtkIdType>(ids->GetComponent(h, 0));
    if (p >= 0 && p < nMesh && local[p] >= 0 && model->HeartIndex[local[p]] < 0)
    {
      model->HeartIndex[local[p]] = h;
      model->Fixed[local[p]] = !model->Source;
      ++nFixed;
    }
  }
  if (nFixed == 0)
  {
    vtkErrorMacro(<< "the torso does not touch the heart: no torso node is a heart node (are both inputs from the "
                     "same mesh?)");
    return false;
  }
  // Torso parts without a heart node have no defined potential: hold them at 0.
  const vtkIdType floating = Ground(fem, model->HeartIndex, model->Source, model->Fixed);
  if (floating)
    vtkWarningMacro(<< floating << " torso nodes lie in parts that touch no heart node; their potential is held at 0");

  // Conductivity per tetrahedron.
  std::vector<std::array<double, 6>> tensors, intra;
  TorsoTensors(regions, torsoCells, inHeart, this->RegionConductivities, this->Conductivity,
    this->IntracellularConductivity, tensors, intra);
  this->UpdateProgress(0.02);
  amSparseMatrix mass;
  fem.Assemble(&tensors, mass, model->K);
  if (model->Source)
  {
    amSparseMatrix unused;
    fem.Assemble(&intra, unused, model->Ki);
    model->Vm.assign(n, 0.0);
    model->Rhs.assign(n, 0.0);
  }
  this->FactorSeconds = 0;
  this->FactorNonZeros = 0;
  if (this->Solver == DIRECT)
  {
    this->UpdateProgress(0.03);
    if (!model->Cholesky.Factor(&model->K, &model->Fixed))
    {
      vtkErrorMacro(<< "cannot factor the torso matrix (" << n << " nodes): " << model->Cholesky.Error()
                    << "; the CONJUGATE_GRADIENT solver needs no factor");
      return false;
    }
    this->FactorSeconds = model->Cholesky.FactorSeconds();
    this->FactorNonZeros = model->Cholesky.FactorNonZeros();
  }
  else
  {
    model->CG.SetMatrix(&model->K, &model->Fixed);
    model->CG.RelativeTolerance = this->SolverTolerance;
    model->CG.MaximumIterations = this->MaximumIterations;
  }
  model->X.assign(n, 0.0);
  model->Zero.assign(n, 0.0);

  // Body surface: faces of exactly one torso tetrahedron (oriented outwards), not all of whose
  // nodes are heart nodes.
  std::vector<unsigned char> onSurface;
  model->Body = BodySurface(subset, model->HeartIndex, model->BodyNodes, onSurface); // output 2
  std::vector<std::array<double, 3>>().swap(model->ElectrodePoints);
  std::vector<vtkIdType> nearest;
  std::vector<double> distances;
  amLeadFields::Snap(fem, onSurface, this->ActiveElectrodes, nearest, distances);
  for (std::size_t k = 0; k < nearest.size(); ++k)
  {
    const std::size_t e = 3 * k;
    if (nearest[k] < 0)
    {
      vtkErrorMacro(<< "the torso has no body surface to put electrodes on");
      return false;
    }
    if (distances[k] > 30.0)
      vtkWarningMacro(<< "electrode " << k << " at (" << this->ActiveElectrodes[e] << ", "
                      << this->ActiveElectrodes[e + 1] << ", " << this->ActiveElectrodes[e + 2] << ") is "
                      << distances[k] << " mm from the closest body-surface node");
    model->Electrodes.push_back(nearest[k]);
    model->ElectrodePoints.push_back(fem.Points[nearest[k]]);
  }

  auto torso = subset.MakeGrid(regions); // output 0: geometry, Region, InputPointId
  amProvenance::Record(
    torso, heart, "amTorsoPotential", this->ProvenanceParameters(model->Source, model->Electrodes.size()));
  model->Torso = torso;
  model->MeshTime = mesh->GetMTime();
  model->FilterTime = this->GetMTime();
  model->HeartRun = amSimulationRun::Of(heart);
  this->NumberOfTorsoNodes = n;
  this->NumberOfHeartNodes = nFixed;
  this->State = std::move(model);
  return true;
}

bool amTorsoPotential::Solve(vtkUnstructuredGrid* heart, double time)
{
  Model& m = *this->State;
  vtkDataArray* potential = heart->GetPointData()->GetArray(this->PotentialArrayName ? this->PotentialArrayName : "");
  if (!potential || amSimulationRun::Of(heart) != m.HeartRun)
  {
    vtkErrorMacro(<< "the heart input changed while the torso series was being computed");
    return false;
  }
  const vtkIdType n = static_cast<vtkIdType>(m.X.size());
  for (vtkIdType i = 0; i < n; ++i)
    if (m.HeartIndex[i] >= 0)
    {
      const double value = potential->GetComponent(m.HeartIndex[i], 0);
      if (!std::isfinite(value))
      {
        vtkErrorMacro(<< "the heart potential is not finite at heart point " << m.HeartIndex[i] << " (t = " << time
                      << " ms)");
        return false;
      }
      (m.Source ? m.Vm[i] : m.X[i]) = this->PotentialScale * value;
    }
  const double* rhs = m.Zero.data();
  if (m.Source)
  {
    m.Ki.Multiply(m.Vm.data(), m.Rhs.data());
    for (double& b : m.Rhs)
      b = -b;
    rhs = m.Rhs.data();
  }
  if (this->Solver == DIRECT)
  {
    if (m.Source)
      m.PendingRhs.insert(m.PendingRhs.end(), m.Rhs.begin(), m.Rhs.end());
    m.Pending.insert(m.Pending.end(), m.X.begin(), m.X.end());
    m.PendingTimes.push_back(time);
    return static_cast<int>(m.PendingTimes.size()) < Model::Batch || this->Flush();
  }
  const auto start = std::chrono::steady_clock::now();
  const amConjugateGradient::Result result = m.CG.Solve(rhs, m.X.data());
  m.Seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m.Iterations += result.Iterations;
  if (!result.Converged)
  {
    vtkErrorMacro(<< "conjugate gradients did not converge for the torso at t = " << time << " ms ("
                  << result.Iterations << " iterations, residual " << result.ResidualNorm << " of "
                  << result.RightHandSideNorm << ")");
    return false;
  }
  m.Record(time, m.X.data());
  return true;
}

bool amTorsoPotential::Flush()
{
  Model& m = *this->State;
  const int count = static_cast<int>(m.PendingTimes.size());
  if (count == 0)
    return true;
  const auto start = std::chrono::steady_clock::now();
  const bool ok = m.Cholesky.Solve(m.Source ? m.PendingRhs.data() : nullptr, m.Pending.data(), count);
  m.Seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!ok)
  {
    vtkErrorMacro(<< "out of memory solving " << count << " torso time steps at once");
    return false;
  }
  for (int k = 0; k < count; ++k)
    m.Record(m.PendingTimes[k], m.Pending.data() + k * m.X.size());
  m.Pending.clear();
  m.PendingRhs.clear();
  m.PendingTimes.clear();
  return true;
}

void amTorsoPotential::Produce(vtkInformationVector* outputVector)
{
  const Model& m = *this->State;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outInfo);
  std::size_t frame = m.Times.size() - 1;
  vtkInformation* timeInfo = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo
    : outputVector->GetInformationObject(2);
  if (timeInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) && m.Times.size() > 1)
  {
    const double t = timeInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    frame = 0;
    while (frame + 1 < m.Times.size() && m.Times[frame + 1] <= t + 1e-9 * std::max(1.0, std::fabs(t)))
      ++frame;
  }
  output->ShallowCopy(m.Torso);
  vtkNew<vtkFloatArray> phi;
  phi->SetName("Potential");
  phi->SetNumberOfTuples(static_cast<vtkIdType>(m.Phi[frame].size()));
  std::copy(m.Phi[frame].begin(), m.Phi[frame].end(), phi->GetPointer(0));
  output->GetPointData()->AddArray(phi);
  output->GetPointData()->SetActiveScalars("Potential");
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), m.Times[frame]);

  vtkPolyData* body = vtkPolyData::GetData(outputVector->GetInformationObject(2));
  body->ShallowCopy(m.Body);
  vtkNew<vtkFloatArray> bodyPhi;
  bodyPhi->SetName("Potential");
  bodyPhi->SetNumberOfTuples(static_cast<vtkIdType>(m.BodyNodes.size()));
  for (std::size_t k = 0; k < m.BodyNodes.size(); ++k)
    bodyPhi->SetValue(static_cast<vtkIdType>(k), m.Phi[frame][m.BodyNodes[k]]);
  body->GetPointData()->AddArray(bodyPhi);
  body->GetPointData()->SetActiveScalars("Potential");
  body->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), m.Times[frame]);

  vtkTable* table = vtkTable::GetData(outputVector->GetInformationObject(1));
  table->Initialize();
  const std::size_t nt = m.Times.size();
  auto column = [&](const char* name) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(static_cast<vtkIdType>(nt));
    table->AddColumn(a);
    return a.GetPointer();
  };
  vtkDoubleArray* time = column("Time");
  amUnits::Set(time, "ms");
  for (std::size_t k = 0; k < nt; ++k)
    time->SetValue(static_cast<vtkIdType>(k), m.Times[k]);
  const std::size_t ne = m.Electrodes.size();
  if (ne == 9)
  {
    static const char* names[12] = { "I", "II", "III", "aVR", "aVL", "aVF", "V1", "V2", "V3", "V4", "V5", "V6" };
    vtkDoubleArray* cols[12];
    for (int l = 0; l < 12; ++l)
      cols[l] = column(names[l]);
    for (std::size_t k = 0; k < nt; ++k)
    {
      const auto& e = m.Leads[k];
      const double ra = e[0], la = e[1], ll = e[2], wct = (ra + la + ll) / 3.0;
      const double lead[12] = { la - ra, ll - ra, ll - la, ra - 0.5 * (la + ll), la - 0.5 * (ra + ll),
        ll - 0.5 * (ra + la), e[3] - wct, e[4] - wct, e[5] - wct, e[6] - wct, e[7] - wct, e[8] - wct };
      for (int l = 0; l < 12; ++l)
        cols[l]->SetValue(static_cast<vtkIdType>(k), lead[l]);
    }
  }
  else
  {
    std::vector<double> means(nt);
    for (std::size_t k = 0; k < nt; ++k)
      means[k] = std::accumulate(m.Leads[k].begin(), m.Leads[k].end(), 0.0) / static_cast<double>(ne);
    for (std::size_t e = 0; e < ne; ++e)
    {
      const std::string name = "E" + std::to_string(e);
      vtkDoubleArray* col = column(name.c_str());
      for (std::size_t k = 0; k < nt; ++k)
        col->SetValue(static_cast<vtkIdType>(k), m.Leads[k][e] - means[k]);
    }
  }
  vtkNew<vtkDoubleArray> electrodes;
  electrodes->SetName("Electrodes");
  electrodes->SetNumberOfComponents(3);
  for (const auto& p : m.ElectrodePoints)
    electrodes->InsertNextTuple(p.data());
  table->GetFieldData()->AddArray(electrodes);
  this->NumberOfSolves = static_cast<int>(nt);
  this->MeanIterations = nt ? static_cast<double>(m.Iterations) / static_cast<double>(nt) : 0.0;
  this->WallSeconds = m.Seconds;
}

int amTorsoPotential::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* mesh = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkUnstructuredGrid* heart = vtkUnstructuredGrid::GetData(inputVector[1]);
  if (!mesh || !heart)
  {
    vtkErrorMacro(<< "TorsoPotential needs the whole mesh (input 0) and the heart solution (input 1)");
    return 0;
  }
  auto fail = [&]() {
    this->LoopIndex = -1;
    this->State.reset();
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    return 0;
  };
  if (this->LoopIndex < 0)
  {
    vtkPolyData* landmarks = vtkPolyData::GetData(inputVector[2], 0);
    const vtkMTimeType landmarksTime = landmarks ? landmarks->GetMTime() : 0;
    const bool valid = this->State && !this->State->Times.empty() && this->State->MeshTime == mesh->GetMTime() &&
      this->State->FilterTime == this->GetMTime() && this->State->HeartRun == amSimulationRun::Of(heart) &&
      this->State->LandmarksTime == landmarksTime;
    if (valid)
    {
      this->Produce(outputVector);
      return 1;
    }
    // The electrodes: the landmarks' RA, LA, LL, V1..V6 where they are connected.
    this->ActiveElectrodes = this->ElectrodePositions;
    if (landmarks)
    {
      std::string why;
      if (!amLandmarkPoints::Named(
            landmarks, { "RA", "LA", "LL", "V1", "V2", "V3", "V4", "V5", "V6" }, this->ActiveElectrodes, why))
      {
        vtkErrorMacro("The electrodes cannot be taken from the Landmarks input: " << why << ".");
        return fail();
      }
    }
    if (!this->Prepare(mesh, heart))
      return fail();
    this->State->LandmarksTime = landmarksTime;
    vtkInformation* heartInfo = inputVector[1]->GetInformationObject(0);
    const int nt = heartInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
      ? heartInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
      : 0;
    if (nt <= 1)
    {
      const double t = heart->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP())
        ? heart->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP())
        : 0.0;
      if (!this->Solve(heart, t) || !this->Flush())
        return fail();
      this->Produce(outputVector);
      return 1;
    }
    const double* times = heartInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    this->LoopTimes.assign(times, times + nt);
    this->LoopIndex = 0;
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
    return 1;
  }
  // Inside the loop: the heart is at LoopTimes[LoopIndex].
  if (!this->Solve(heart, this->LoopTimes[this->LoopIndex]))
    return fail();
  ++this->LoopIndex;
  this->UpdateProgress(0.05 + 0.95 * this->LoopIndex / static_cast<double>(this->LoopTimes.size()));
  if (this->LoopIndex < static_cast<int>(this->LoopTimes.size()))
  {
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
    return 1;
  }
  if (!this->Flush())
    return fail();
  request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
  this->LoopIndex = -1;
  this->Produce(outputVector);
  return 1;
}

void amTorsoPotential::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Conductivity: " << this->Conductivity << "\n";
  os << indent << "PotentialScale: " << this->PotentialScale << "\n";
  os << indent << "Electrodes: " << this->ElectrodePositions.size() / 3 << "\n";
  os << indent << "Coupling: " << (this->Coupling == DIRICHLET ? "DIRICHLET" : "CURRENT_SOURCE") << "\n";
  os << indent << "IntracellularConductivity: " << this->IntracellularConductivity << "\n";
  os << indent << "Solver: " << (this->Solver == DIRECT ? "DIRECT" : "CONJUGATE_GRADIENT") << "\n";
  os << indent << "SolverTolerance: " << this->SolverTolerance << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
}
