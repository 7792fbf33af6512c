#include "amVentricularFibres.h"

#include "amLandmarkPoints.h"
#include "amProvenance.h"
#include "amRuleBasedFibres.h"
#include "amTetraFaces.h"
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
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <Eigen/Dense>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

vtkStandardNewMacro(amVentricularFibres);

namespace
{
void AddTo(std::vector<int>& list, int label, vtkObject* self)
{
  list.push_back(label);
  self->Modified();
}

void Clear(std::vector<int>& list, vtkObject* self)
{
  if (!list.empty())
  {
    list.clear();
    self->Modified();
  }
}

// The main axis of the LV endocardium's nodes, turned towards the base triangles' nodes; where
// there are none (a heart meshed without its outflow tracts and atria), towards the patient's
// right, back and head (LPS -x, +y, +z), where a heart's base lies and its apex does not.
bool AxisFromSurfaces(const amP1Assembly& fem, const std::vector<unsigned char>& tag, double axis[3])
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), base = Eigen::Vector3d::Zero();
  double n = 0, nb = 0;
  for (std::size_t i = 0; i < tag.size(); ++i)
  {
    const Eigen::Vector3d x(fem.Points[i][0], fem.Points[i][1], fem.Points[i][2]);
    if (tag[i] == amVentricularTags::LVEndocardium)
    {
      mean += x;
      ++n;
    }
    else if (tag[i] == amVentricularTags::Base)
    {
      base += x;
      ++nb;
    }
  }
  if (n < 4)
    return false;
  mean /= n;
  base = nb > 0 ? Eigen::Vector3d(base / nb) : Eigen::Vector3d(mean + Eigen::Vector3d(-1, 1, 1));
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < tag.size(); ++i)
    if (tag[i] == amVentricularTags::LVEndocardium)
    {
      const Eigen::Vector3d d = Eigen::Vector3d(fem.Points[i][0], fem.Points[i][1], fem.Points[i][2]) - mean;
      cov += d * d.transpose();
    }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d a = eig.eigenvectors().col(2);
  if (a.dot(base - mean) < 0)
    a = -a;
  for (int c = 0; c < 3; ++c)
    axis[c] = a[c];
  return true;
}
}

amVentricularFibres::amVentricularFibres()
  : RegionArrayName(nullptr)
  , HeartRegions{ 5 }
  , LVBloodRegions{ 6 }
  , RVBloodRegions{ 7 }
  , BaseRegions{ 8, 11 }
  , HelixEndocardium(60.0)
  , HelixEpicardium(-60.0)
  , TransverseEndocardium(0.0)
  , TransverseEpicardium(0.0)
  , ApexToBase{ 0, 0, 0 }
  , NumberOfHeartCells(0)
  , TagCounts{ 0, 0, 0, 0, 0 }
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetRegionArrayName("Region");
}

amVentricularFibres::~amVentricularFibres()
{
  this->SetRegionArrayName(nullptr);
}

void amVentricularFibres::AddHeartRegion(int label)
{
  AddTo(this->HeartRegions, label, this);
}
void amVentricularFibres::RemoveAllHeartRegions()
{
  Clear(this->HeartRegions, this);
}
void amVentricularFibres::AddLVBloodRegion(int label)
{
  AddTo(this->LVBloodRegions, label, this);
}
void amVentricularFibres::RemoveAllLVBloodRegions()
{
  Clear(this->LVBloodRegions, this);
}
void amVentricularFibres::AddRVBloodRegion(int label)
{
  AddTo(this->RVBloodRegions, label, this);
}
void amVentricularFibres::RemoveAllRVBloodRegions()
{
  Clear(this->RVBloodRegions, this);
}
void amVentricularFibres::AddBaseRegion(int label)
{
  AddTo(this->BaseRegions, label, this);
}
void amVentricularFibres::RemoveAllBaseRegions()
{
  Clear(this->BaseRegions, this);
}

int amVentricularFibres::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 1 ? "vtkPolyData" : "vtkUnstructuredGrid");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int amVentricularFibres::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

namespace
{
// The apex-to-base axis: from the landmarks (LVApexEpicardium to LVBase) when connected, else the
// given one, else found from the LV endocardium and base surfaces. 'from' says which; false with
// 'why' when none can be had.
bool LongAxis(vtkPolyData* landmarks, const double given[3], const amP1Assembly& fem,
  const std::vector<unsigned char>& nodeTag, double axis[3], std::string& from, std::string& why)
{
  std::copy(given, given + 3, axis);
  from = "ApexToBase";
  if (landmarks)
  {
    std::vector<double> x;
    if (!amLandmarkPoints::Named(landmarks, { "LVApexEpicardium", "LVBase" }, x, why))
    {
      why = "The long axis cannot be taken from the Landmarks input: " + why + ".";
      return false;
    }
    for (int c = 0; c < 3; ++c)
      axis[c] = x[3 + c] - x[c];
    from = "Landmarks";
  }
  else if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0)
  {
    from = "LV endocardium";
    if (!AxisFromSurfaces(fem, nodeTag, axis))
    {
      why = "no apex-to-base axis: connect Landmarks or set ApexToBase";
      return false;
    }
  }
  return true;
}

// The output: the input with the fibres and sheets per heart tetrahedron (0 elsewhere) and, per
// node, the transmural depth, the apico-basal coordinate and the ventricle (-1 off the heart).
void AddFibres(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, const std::vector<vtkIdType>& heartCells,
  const amTetraSubset& subset, const amRuleBasedFibres& fibres)
{
  const vtkIdType nCells = input->GetNumberOfCells();
  output->ShallowCopy(input);
  vtkNew<vtkFloatArray> fibreArray, sheetArray;
  fibreArray->SetName("Fibers");
  sheetArray->SetName("Sheets");
  for (auto* a : { fibreArray.GetPointer(), sheetArray.GetPointer() })
  {
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(nCells);
    a->FillValue(0.0f);
  }
  for (std::size_t k = 0; k < heartCells.size(); ++k)
  {
    fibreArray->SetTuple(heartCells[k], fibres.Fibres[k].data());
    sheetArray->SetTuple(heartCells[k], fibres.Sheets[k].data());
  }
  output->GetCellData()->AddArray(fibreArray);
  output->GetCellData()->AddArray(sheetArray);
  const vtkIdType nPoints = input->GetNumberOfPoints();
  vtkNew<vtkFloatArray> depth, apicoBasal;
  vtkNew<vtkIntArray> ventricle;
  depth->SetName("TransmuralDepth");
  apicoBasal->SetName("ApicoBasal");
  ventricle->SetName("Ventricle");
  depth->SetNumberOfTuples(nPoints);
  apicoBasal->SetNumberOfTuples(nPoints);
  ventricle->SetNumberOfTuples(nPoints);
  for (vtkIdType p = 0; p < nPoints; ++p)
  {
    const vtkIdType i = subset.Local[p];
    depth->SetValue(p, i < 0 ? -1.0f : static_cast<float>(fibres.TransmuralDepth[i]));
    apicoBasal->SetValue(p, i < 0 ? -1.0f : static_cast<float>(fibres.ApicoBasal[i]));
    ventricle->SetValue(p, i < 0 ? -1 : fibres.Ventricle[i]);
  }
  output->GetPointData()->AddArray(depth);
  output->GetPointData()->AddArray(apicoBasal);
  output->GetPointData()->AddArray(ventricle);
}

// The tagged triangles as a surface of their own, its points those of the input they came from.
void AddTags(const std::vector<amVentricularTags::Triangle>& triangles, const std::vector<double>& xyz,
  vtkIdType nPoints, vtkPolyData* tagsOut)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::vector<vtkIdType> local(nPoints, -1);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdTypeArray> inputIds;
  inputIds->SetName("InputPointId");
  vtkNew<vtkIntArray> tagArray;
  tagArray->SetName("VentricularTag");
  for (const auto& t : triangles)
  {
    vtkIdType ids[3];
    for (int a = 0; a < 3; ++a)
    {
      if (local[t.Points[a]] < 0)
      {
        local[t.Points[a]] = points->InsertNextPoint(&xyz[3 * t.Points[a]]);
        inputIds->InsertNextValue(t.Points[a]);
      }
      ids[a] = local[t.Points[a]];
    }
    polys->InsertNextCell(3, ids);
    tagArray->InsertNextValue(t.Tag);
  }
  tagsOut->SetPoints(points);
  tagsOut->SetPolys(polys);
  tagsOut->GetCellData()->AddArray(tagArray);
  tagsOut->GetPointData()->AddArray(inputIds);
  vtkNew<vtkStringArray> names;
  names->SetName("TagNames");
  for (int t = 1; t <= 4; ++t)
    names->InsertNextValue(std::to_string(t) + " " + amVentricularTags::Name(t));
  tagsOut->GetFieldData()->AddArray(names);
}

}

int amVentricularFibres::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkPolyData* landmarks = vtkPolyData::GetData(inputVector[1], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* tagsOut = vtkPolyData::GetData(outputVector, 1);
  if (!input)
  {
    vtkErrorMacro(<< "no input mesh");
    return 0;
  }
  vtkDataArray* regions = this->RegionArrayName ? input->GetCellData()->GetArray(this->RegionArrayName) : nullptr;
  if (!regions)
  {
    vtkErrorMacro(<< "the mesh has no cell array '" << (this->RegionArrayName ? this->RegionArrayName : "")
                  << "' of region labels: the ventricles are found from the labels around the heart");
    return 0;
  }
  const vtkIdType nCells = input->GetNumberOfCells();
  const std::set<int> heart(this->HeartRegions.begin(), this->HeartRegions.end());
  std::vector<int> labels(nCells);
  std::vector<vtkIdType> tetCells, heartCells;
  std::vector<int> tetLabels;
  for (vtkIdType c = 0; c < nCells; ++c)
  {
    labels[c] = static_cast<int>(regions->GetComponent(c, 0));
    if (input->GetCellType(c) != VTK_TETRA)
    {
      if (heart.count(labels[c]))
      {
        vtkErrorMacro(<< "cell " << c << " of the heart is not a tetrahedron (VTK cell type " << input->GetCellType(c)
                      << ")");
        return 0;
      }
      continue;
    }
    tetCells.push_back(c);
    tetLabels.push_back(labels[c]);
    if (heart.count(labels[c]))
      heartCells.push_back(c);
  }
  if (heartCells.empty())
  {
    vtkErrorMacro(<< "no heart: no tetrahedron has a label among HeartRegions");
    return 0;
  }

  // The heart's boundary triangles, tagged by the region across them.
  std::vector<double> xyz(3 * input->GetNumberOfPoints());
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
    input->GetPoint(p, &xyz[3 * p]);
  std::vector<std::array<vtkIdType, 4>> tets(tetCells.size());
  for (std::size_t k = 0; k < tetCells.size(); ++k)
  {
    const vtkIdType* ids;
    vtkIdType npts;
    input->GetCellPoints(tetCells[k], npts, ids);
    std::copy(ids, ids + 4, tets[k].begin());
  }
  amVentricularTags tagger;
  tagger.Heart = heart;
  tagger.LVBlood.insert(this->LVBloodRegions.begin(), this->LVBloodRegions.end());
  tagger.RVBlood.insert(this->RVBloodRegions.begin(), this->RVBloodRegions.end());
  tagger.BaseRegions.insert(this->BaseRegions.begin(), this->BaseRegions.end());
  std::map<std::pair<int, int>, vtkIdType> holes;
  const std::vector<amVentricularTags::Triangle> triangles = tagger.Find(xyz.data(), tets, tetLabels, &holes);
  this->NumberOfWallHoles = this->WarnOfWallHoles(holes);
  this->UpdateProgress(0.1);

  amTetraSubset subset;
  subset.Build(input, heartCells);
  const vtkIdType n = static_cast<vtkIdType>(subset.Global.size());
  std::vector<unsigned char> nodeTag(n, 0);
  std::fill(this->TagCounts, this->TagCounts + 5, 0);
  // Endocardium first: a node on the endocardium and another surface is endocardial.
  auto rank = [](unsigned char t) { return t == 0 ? 0 : (t <= 2 ? 3 : (t == amVentricularTags::Epicardium ? 2 : 1)); };
  for (const auto& t : triangles)
  {
    ++this->TagCounts[t.Tag];
    for (vtkIdType p : t.Points)
    {
      unsigned char& nt = nodeTag[subset.Local[p]];
      if (rank(t.Tag) > rank(nt))
        nt = t.Tag;
    }
  }
  this->NumberOfHeartCells = static_cast<vtkIdType>(heartCells.size());
  if (this->TagCounts[amVentricularTags::LVEndocardium] == 0)
  {
    std::ostringstream regionsAcross;
    std::set<int> across;
    for (const auto& t : triangles)
      across.insert(t.Across);
    for (int l : across)
      regionsAcross << " " << (l == amTetraFaces::Outside() ? std::string("outside") : std::to_string(l));
    vtkErrorMacro(<< "no LV endocardium: no heart triangle faces a region of LVBloodRegions; the heart is bounded by"
                  << regionsAcross.str());
    return 0;
  }

  amRuleBasedFibres::Parameters parameters;
  parameters.HelixEndocardium = this->HelixEndocardium;
  parameters.HelixEpicardium = this->HelixEpicardium;
  parameters.TransverseEndocardium = this->TransverseEndocardium;
  parameters.TransverseEpicardium = this->TransverseEpicardium;
  double axis[3];
  std::string axisFrom, why;
  if (!LongAxis(landmarks, this->ApexToBase, subset.Fem, nodeTag, axis, axisFrom, why))
  {
    if (axisFrom == "LV endocardium")
      vtkErrorMacro(<< why << " (the mesh has " << this->TagCounts[amVentricularTags::LVEndocardium]
                    << " LV endocardial and " << this->TagCounts[amVentricularTags::Base]
                    << " base triangles to find it from)");
    else
      vtkErrorMacro(<< why);
    return 0;
  }
  const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (!(length > 0))
  {
    vtkErrorMacro(<< "the apex-to-base axis from " << axisFrom << " is zero");
    return 0;
  }
  for (int c = 0; c < 3; ++c)
    this->UsedApexToBase[c] = axis[c] / length;
  std::copy(axis, axis + 3, parameters.ApexToBase.begin());
  amRuleBasedFibres fibres;
  if (!fibres.Compute(subset.Fem, nodeTag, parameters))
  {
    vtkErrorMacro(<< "no fibres: " << fibres.Error);
    return 0;
  }
  this->UpdateProgress(0.9);

  AddFibres(input, output, heartCells, subset, fibres);
  AddTags(triangles, xyz, input->GetNumberOfPoints(), tagsOut);

  std::ostringstream params;
  params << "Helix=" << this->HelixEndocardium << "/" << this->HelixEpicardium
         << " Transverse=" << this->TransverseEndocardium << "/" << this->TransverseEpicardium << " Axis=(" << axis[0]
         << "," << axis[1] << "," << axis[2] << ") from " << axisFrom;
  amProvenance::Record(output, input, "amVentricularFibres", params.str());
  return 1;
}

vtkIdType amVentricularFibres::WarnOfWallHoles(const std::map<std::pair<int, int>, vtkIdType>& holes)
{
  // Ventricular blood touching anything but the heart, the other pool or the base: a hole in the
  // segmented wall (the activation and the ECG then miss that part of the wall).
  vtkIdType total = 0;
  for (const auto& kv : holes)
    total += kv.second;
  if (total > 0)
  {
    std::ostringstream text;
    text << "the heart wall has holes: ";
    bool first = true;
    for (const auto& kv : holes)
    {
      text << (first ? "" : ", ") << "blood region " << kv.first.first << " touches "
           << (kv.first.second == amTetraFaces::Outside() ? std::string("the outside")
                                                          : "region " + std::to_string(kv.first.second))
           << " on " << kv.second << " triangles";
      first = false;
    }
    text << " (HeartRegions, LVBloodRegions, RVBloodRegions and BaseRegions name what the blood may touch)";
    vtkWarningMacro(<< text.str());
  }
  return total;
}

void amVentricularFibres::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Helix: " << this->HelixEndocardium << " to " << this->HelixEpicardium << "\n";
  os << indent << "Transverse: " << this->TransverseEndocardium << " to " << this->TransverseEpicardium << "\n";
  os << indent << "ApexToBase: " << this->ApexToBase[0] << " " << this->ApexToBase[1] << " " << this->ApexToBase[2]
     << "\n";
}
