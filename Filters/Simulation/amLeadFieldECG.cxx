#include "amLeadFieldECG.h"

#include "amECGFeatures.h"
#include "amLandmarkPoints.h"
#include "amLeadFields.h"
#include "amP1Assembly.h"
#include "amProvenance.h"
#include "amSimulationRun.h"
#include "amTetraFaces.h"
#include "amThoraxPhantomModel.h"
#include "amTwelveLeads.h"
#include "amUnits.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

vtkStandardNewMacro(amLeadFieldECG);

struct amLeadFieldECG::Model
{
  vtkMTimeType MeshTime = 0, FilterTime = 0, LandmarksTime = 0;
  long long HeartRun = -1;
  amLeadFields Fields;
  std::vector<vtkIdType> HeartPointOfNode; // per Fields.Nodes entry: the heart's point id
  std::vector<std::array<double, 3>> Electrodes;
  std::vector<double> Times;
  std::vector<std::array<double, 12>> Leads;
};

amLeadFieldECG::amLeadFieldECG()
  : RegionArrayName(nullptr)
  , FiberArrayName(nullptr)
  , VoltageArrayName(nullptr)
  , IntracellularConductivityFibre(0.17)
  , IntracellularConductivityTransverse(0.019)
  , ExtracellularConductivityFibre(0.62)
  , ExtracellularConductivityTransverse(0.24)
  , Conductivity(0.2)
  , RegionConductivities{ 1, 0.2, 2, 0.04, 3, 0.05, 4, 0.05, 6, 0.7, 7, 0.7, 8, 0.7, 9, 0.02, 10, 0.02, 11, 0.7, 12,
    0.05 }
  , MaximumElectrodeDistance(20.0)
  , SamplingInterval(1.0)
  , NumberOfNodes(0)
  , NumberOfHeartNodes(0)
  , NumberOfFrames(0)
  , LeadFieldSeconds(0)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(2);
  this->SetRegionArrayName("Region");
  this->SetFiberArrayName("Fibers");
  this->SetVoltageArrayName("Vm");
  double electrodes[9][3];
  amThoraxPhantomModel::StandardElectrodes(electrodes);
  for (const auto& e : electrodes)
    this->ElectrodePositions.insert(this->ElectrodePositions.end(), e, e + 3);
}

amLeadFieldECG::~amLeadFieldECG()
{
  this->SetRegionArrayName(nullptr);
  this->SetFiberArrayName(nullptr);
  this->SetVoltageArrayName(nullptr);
}

void amLeadFieldECG::AddRegionConductivity(double label, double sigma)
{
  this->RegionConductivities.push_back(label);
  this->RegionConductivities.push_back(sigma);
  this->Modified();
}

void amLeadFieldECG::RemoveAllRegionConductivities()
{
  if (!this->RegionConductivities.empty())
  {
    this->RegionConductivities.clear();
    this->Modified();
  }
}

void amLeadFieldECG::AddElectrode(double x, double y, double z)
{
  this->ElectrodePositions.insert(this->ElectrodePositions.end(), { x, y, z });
  this->Modified();
}

void amLeadFieldECG::RemoveAllElectrodes()
{
  if (!this->ElectrodePositions.empty())
  {
    this->ElectrodePositions.clear();
    this->Modified();
  }
}

int amLeadFieldECG::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 2 ? "vtkPolyData" : "vtkUnstructuredGrid");
  if (port == 2)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int amLeadFieldECG::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkTable");
  return 1;
}

int amLeadFieldECG::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  return 1;
}

int amLeadFieldECG::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkInformation* heartInfo = inputVector[1]->GetInformationObject(0);
  if (heartInfo && this->LoopIndex >= 0)
    heartInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), this->LoopTimes[this->LoopIndex]);
  return 1;
}

bool amLeadFieldECG::Prepare(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* heart, vtkPolyData* landmarks)
{
  const auto start = std::chrono::steady_clock::now();
  auto model = std::make_unique<Model>();
  vtkDataArray* regions = this->RegionArrayName ? mesh->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  vtkDataArray* heartRegions = this->RegionArrayName ? heart->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  vtkDataArray* ids = heart->GetPointData()->GetArray("InputPointId");
  if (!regions || !heartRegions || !ids)
  {
    vtkErrorMacro(<< "the mesh and the heart need cell data '" << (this->RegionArrayName ? this->RegionArrayName : "")
                  << "' and the heart point data InputPointId (the heart solvers' output has both)");
    return false;
  }
  std::set<int> heartLabels;
  for (vtkIdType c = 0; c < heart->GetNumberOfCells(); ++c)
    heartLabels.insert(static_cast<int>(heartRegions->GetComponent(c, 0)));
  vtkDataArray* fibres = this->FiberArrayName ? mesh->GetCellData()->GetArray(this->FiberArrayName) : nullptr;
  if (fibres && fibres->GetNumberOfComponents() != 3)
    fibres = nullptr;
  std::map<int, double> sigmaOf;
  for (std::size_t k = 0; k + 1 < this->RegionConductivities.size(); k += 2)
    sigmaOf[static_cast<int>(this->RegionConductivities[k])] = this->RegionConductivities[k + 1];

  amP1Assembly fem;
  const vtkIdType np = mesh->GetNumberOfPoints();
  fem.Points.resize(np);
  for (vtkIdType p = 0; p < np; ++p)
    mesh->GetPoint(p, fem.Points[p].data());
  std::vector<std::array<double, 6>> bulk, intracellular;
  std::vector<vtkIdType> heartTets;
  std::vector<int> labels;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    if (mesh->GetCellType(c) != VTK_TETRA)
    {
      vtkErrorMacro(<< "cell " << c << " of the mesh is not a tetrahedron (VTK cell type " << mesh->GetCellType(c)
                    << ")");
      return false;
    }
    const vtkIdType* pts;
    vtkIdType npts;
    mesh->GetCellPoints(c, npts, pts);
    fem.Tetrahedra.push_back({ pts[0], pts[1], pts[2], pts[3] });
    const int label = static_cast<int>(regions->GetComponent(c, 0));
    labels.push_back(label);
    if (heartLabels.count(label))
    {
      double f[3] = { 0, 0, 0 };
      if (fibres)
        fibres->GetTuple(c, f);
      const auto si =
        amP1Assembly::FiberTensor(this->IntracellularConductivityFibre, this->IntracellularConductivityTransverse, f);
      const auto se =
        amP1Assembly::FiberTensor(this->ExtracellularConductivityFibre, this->ExtracellularConductivityTransverse, f);
      std::array<double, 6> sb;
      for (int q = 0; q < 6; ++q)
        sb[q] = si[q] + se[q];
      bulk.push_back(sb);
      intracellular.push_back(si);
      heartTets.push_back(static_cast<vtkIdType>(fem.Tetrahedra.size() - 1));
    }
    else
    {
      const auto it = sigmaOf.find(label);
      const double s = it != sigmaOf.end() ? it->second : this->Conductivity;
      const double none[3] = { 0, 0, 0 };
      bulk.push_back(amP1Assembly::FiberTensor(s, s, none));
    }
  }
  if (heartTets.empty())
  {
    vtkErrorMacro(<< "no tetrahedron of the mesh has a region of the heart's cells");
    return false;
  }
  const vtkIdType bad = fem.FindDegenerate();
  if (bad >= 0)
  {
    vtkErrorMacro(<< "tetrahedron " << bad << " is degenerate (flat, collapsed or with a non-finite coordinate)");
    return false;
  }

  // The electrodes on the body surface.
  std::vector<double> positions = this->ElectrodePositions;
  if (landmarks)
  {
    std::string why;
    if (!amLandmarkPoints::Named(landmarks, amTwelveLeads::ElectrodeNames(), positions, why))
    {
      vtkErrorMacro("The electrodes cannot be taken from the Landmarks input: " << why << ".");
      return false;
    }
  }
  if (positions.size() != 27)
  {
    vtkErrorMacro(<< "the 12 leads need 9 electrodes (RA, LA, LL, V1..V6); " << positions.size() / 3 << " are given");
    return false;
  }
  std::vector<unsigned char> onSurface(np, 0);
  for (const auto& face : amTetraFaces::Find(&fem.Points[0][0], fem.Tetrahedra, nullptr))
    for (vtkIdType v : face.Points)
      onSurface[v] = 1;
  std::vector<vtkIdType> electrodes;
  std::vector<double> distances;
  amLeadFields::Snap(fem, onSurface, positions, electrodes, distances);
  for (std::size_t e = 0; e < electrodes.size(); ++e)
    if (electrodes[e] < 0 || distances[e] > this->MaximumElectrodeDistance)
    {
      vtkErrorMacro(<< "electrode " << amTwelveLeads::ElectrodeNames()[e] << " at (" << positions[3 * e] << ", "
                    << positions[3 * e + 1] << ", " << positions[3 * e + 2] << ") is off the body: "
                    << (electrodes[e] < 0 ? std::string("the mesh has no surface")
                                          : std::to_string(distances[e]) + " mm from the nearest body-surface node")
                    << " (MaximumElectrodeDistance " << this->MaximumElectrodeDistance << " mm)");
      return false;
    }
  this->UpdateProgress(0.05);
  if (!model->Fields.Compute(fem, bulk, heartTets, intracellular, electrodes, electrodes[0]))
  {
    vtkErrorMacro(<< model->Fields.Error);
    return false;
  }
  // The heart's points of the weighted nodes.
  std::vector<vtkIdType> heartPoint(np, -1);
  for (vtkIdType i = 0; i < heart->GetNumberOfPoints(); ++i)
  {
    const vtkIdType g = static_cast<vtkIdType>(ids->GetComponent(i, 0));
    if (g < 0 || g >= np)
    {
      vtkErrorMacro(<< "the heart's InputPointId " << g << " is not a point of the mesh");
      return false;
    }
    heartPoint[g] = i;
  }
  for (vtkIdType node : model->Fields.Nodes)
  {
    if (heartPoint[node] < 0)
    {
      vtkErrorMacro(<< "mesh point " << node << " of a heart tetrahedron is not in the heart's solution");
      return false;
    }
    model->HeartPointOfNode.push_back(heartPoint[node]);
  }
  for (vtkIdType e : electrodes)
    model->Electrodes.push_back(fem.Points[e]);
  this->NumberOfNodes = np;
  this->NumberOfHeartNodes = static_cast<vtkIdType>(model->Fields.Nodes.size());
  this->LeadFieldSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->State = std::move(model);
  return true;
}

bool amLeadFieldECG::Read(vtkUnstructuredGrid* heart, double time)
{
  vtkDataArray* vm = this->VoltageArrayName ? heart->GetPointData()->GetArray(this->VoltageArrayName) : nullptr;
  if (!vm)
  {
    vtkErrorMacro(<< "the heart has no point data '" << (this->VoltageArrayName ? this->VoltageArrayName : "")
                  << "' (the transmembrane voltage, mV)");
    return false;
  }
  Model& m = *this->State;
  std::vector<double> v(m.HeartPointOfNode.size());
  for (std::size_t j = 0; j < v.size(); ++j)
  {
    v[j] = vm->GetComponent(m.HeartPointOfNode[j], 0);
    if (!std::isfinite(v[j]))
    {
      vtkErrorMacro(<< "the heart's voltage is not finite at point " << m.HeartPointOfNode[j] << ", t = " << time
                    << " ms");
      return false;
    }
  }
  const std::vector<double> phi = m.Fields.Potentials(v);
  m.Times.push_back(time);
  m.Leads.push_back(amTwelveLeads::Leads(phi.data()));
  return true;
}

int amLeadFieldECG::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* mesh = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkUnstructuredGrid* heart = vtkUnstructuredGrid::GetData(inputVector[1]);
  vtkPolyData* landmarks = vtkPolyData::GetData(inputVector[2], 0);
  vtkTable* output = vtkTable::GetData(outputVector, 0);
  vtkTable* features = vtkTable::GetData(outputVector, 1);
  auto fail = [&]() {
    this->LoopIndex = -1;
    this->State.reset();
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    return 0;
  };
  if (!mesh || !heart)
  {
    vtkErrorMacro(<< "LeadFieldECG needs the whole mesh (input 0) and the heart's solution (input 1)");
    return fail();
  }
  if (this->LoopIndex < 0)
  {
    const vtkMTimeType landmarksTime = landmarks ? landmarks->GetMTime() : 0;
    const long long run = amSimulationRun::Of(heart);
    const bool valid = this->State && !this->State->Times.empty() && this->State->HeartRun == run &&
      this->State->MeshTime == mesh->GetMTime() && this->State->FilterTime == this->GetMTime() &&
      this->State->LandmarksTime == landmarksTime;
    if (!valid)
    {
      if (!this->Prepare(mesh, heart, landmarks))
        return fail();
      this->State->MeshTime = mesh->GetMTime();
      this->State->FilterTime = this->GetMTime();
      this->State->LandmarksTime = landmarksTime;
      this->State->HeartRun = run;
      vtkInformation* heartInfo = inputVector[1]->GetInformationObject(0);
      const int nt = heartInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
        ? heartInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
        : 0;
      std::vector<double> loop;
      if (nt > 1)
      {
        const double* times = heartInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
        if (this->SamplingInterval > 0)
        {
          const long long samples =
            std::llround(std::floor((times[nt - 1] - times[0]) / this->SamplingInterval + 1e-9));
          for (long long k = 0; k <= samples; ++k)
            loop.push_back(times[0] + k * this->SamplingInterval);
        }
        else
          loop.assign(times, times + nt);
      }
      if (loop.size() <= 1)
      {
        const double t = heart->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP())
          ? heart->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP())
          : 0.0;
        if (!this->Read(heart, t))
          return fail();
      }
      else
      {
        this->LoopTimes = loop;
        this->LoopIndex = 0;
        request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
        return 1;
      }
    }
  }
  else
  {
    if (!this->Read(heart, this->LoopTimes[this->LoopIndex]))
      return fail();
    ++this->LoopIndex;
    this->UpdateProgress(0.1 + 0.9 * this->LoopIndex / static_cast<double>(this->LoopTimes.size()));
    if (this->LoopIndex < static_cast<int>(this->LoopTimes.size()))
    {
      request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
      return 1;
    }
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    this->LoopIndex = -1;
  }

  const Model& m = *this->State;
  const vtkIdType nt = static_cast<vtkIdType>(m.Times.size());
  vtkNew<vtkDoubleArray> time;
  time->SetName("Time");
  amUnits::Set(time, "ms");
  time->SetNumberOfTuples(nt);
  for (vtkIdType k = 0; k < nt; ++k)
    time->SetValue(k, m.Times[k]);
  output->AddColumn(time);
  for (int l = 0; l < 12; ++l)
  {
    vtkNew<vtkDoubleArray> lead;
    lead->SetName(amTwelveLeads::LeadNames()[l].c_str());
    amUnits::Set(lead, "mV");
    lead->SetNumberOfTuples(nt);
    for (vtkIdType k = 0; k < nt; ++k)
      lead->SetValue(k, m.Leads[k][l]);
    output->AddColumn(lead);
  }
  vtkNew<vtkDoubleArray> electrodes;
  electrodes->SetName("Electrodes");
  electrodes->SetNumberOfComponents(3);
  for (const auto& p : m.Electrodes)
    electrodes->InsertNextTuple(p.data());
  output->GetFieldData()->AddArray(electrodes);
  this->NumberOfFrames = static_cast<int>(nt);
  this->Measure(features);
  std::ostringstream params;
  params << "sigma_i=" << this->IntracellularConductivityFibre << "/" << this->IntracellularConductivityTransverse
         << " sigma_e=" << this->ExtracellularConductivityFibre << "/" << this->ExtracellularConductivityTransverse
         << " Conductivity=" << this->Conductivity << " RegionConductivities=";
  for (std::size_t k = 0; k < this->RegionConductivities.size(); ++k)
    params << (k ? "," : "") << this->RegionConductivities[k];
  amProvenance::Record(output, mesh, "amLeadFieldECG", params.str());
  return 1;
}

void amLeadFieldECG::Measure(vtkTable* features)
{
  const Model& m = *this->State;
  this->QRSDuration = this->QTInterval = 0;
  if (m.Times.size() < 3)
    return; // a single frame is a map, not an ECG
  std::vector<std::vector<double>> leads(12, std::vector<double>(m.Times.size()));
  for (std::size_t k = 0; k < m.Times.size(); ++k)
    for (int l = 0; l < 12; ++l)
      leads[l][k] = m.Leads[k][l];
  amECGFeatures measure;
  if (!measure.Measure(m.Times, amTwelveLeads::LeadNames(), leads))
  {
    vtkWarningMacro(<< "the ECG's features cannot be read: " << measure.Error);
    return;
  }
  this->QRSDuration = measure.QRSDuration;
  this->QTInterval = measure.QTInterval;
  vtkNew<vtkStringArray> name, polarity;
  name->SetName("Lead");
  polarity->SetName("TPolarity");
  vtkNew<vtkDoubleArray> r, s, t;
  r->SetName("R_mV");
  s->SetName("S_mV");
  t->SetName("T_mV");
  for (const auto& lead : measure.Leads)
  {
    name->InsertNextValue(lead.Name);
    r->InsertNextValue(lead.R);
    s->InsertNextValue(lead.S);
    t->InsertNextValue(lead.T);
    polarity->InsertNextValue(lead.TPolarity);
  }
  features->AddColumn(name);
  features->AddColumn(r);
  features->AddColumn(s);
  features->AddColumn(t);
  features->AddColumn(polarity);
  for (const auto& figure : { std::make_pair("QRSOnset_ms", measure.QRSOnset),
         std::make_pair("QRSDuration_ms", measure.QRSDuration), std::make_pair("QTInterval_ms", measure.QTInterval) })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(figure.first);
    a->InsertNextValue(figure.second);
    features->GetFieldData()->AddArray(a);
  }
}

void amLeadFieldECG::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Intracellular: " << this->IntracellularConductivityFibre << " / "
     << this->IntracellularConductivityTransverse << "\n";
  os << indent << "Extracellular: " << this->ExtracellularConductivityFibre << " / "
     << this->ExtracellularConductivityTransverse << "\n";
  os << indent << "Electrodes: " << this->ElectrodePositions.size() / 3 << "\n";
}
