#include "amLabelMapTetrahedralize.h"

#include "amInputCheck.h"
#include "amLabelMapMesh3.h"
#include "amProvenance.h"
#include "amTetraFinish.h"
#include "amTetraGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(amLabelMapTetrahedralize);

amLabelMapTetrahedralize::amLabelMapTetrahedralize()
  : BackgroundLabel(0)
  , FacetDistance(0.5)
  , FacetSize(4.0)
  , FacetAngle(30.0)
  , CellSize(8.0)
  , CellRadiusEdgeRatio(2.0)
  , ProtectJunctions(1)
  , EdgeSize(0.0)
  , Odt(0)
  , Lloyd(0)
  , Perturb(1)
  , Exude(1)
  , SliverBound(12.0)
  , ImproveQuality(1)
  , PreserveVolumes(1)
  , ImprovementPasses(4)
  , MaximumSurfaceDeviation(0.2)
  , NumberOfSlivers(0)
  , SurfaceDeviation(0)
  , NumberOfTetrahedra(0)
{
  this->SetNumberOfOutputPorts(2);
}

amLabelMapTetrahedralize::~amLabelMapTetrahedralize() = default;

void amLabelMapTetrahedralize::AddRegionCellSize(double label, double size)
{
  this->RegionCellSizes.push_back(label);
  this->RegionCellSizes.push_back(size);
  this->Modified();
}

void amLabelMapTetrahedralize::RemoveAllRegionCellSizes()
{
  if (!this->RegionCellSizes.empty())
  {
    this->RegionCellSizes.clear();
    this->Modified();
  }
}

int amLabelMapTetrahedralize::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

int amLabelMapTetrahedralize::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int amLabelMapTetrahedralize::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* interfaces = vtkPolyData::GetData(outputVector, 1);
  this->NumberOfTetrahedra = 0;

  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  int dims[3];
  double spacing[3], origin[3];
  input->GetDimensions(dims);
  input->GetSpacing(spacing);
  input->GetOrigin(origin);
  const double* direction = input->GetDirectionMatrix()->GetData();
  const int bg = this->BackgroundLabel;

  // Any whole-number labels, any count (amLabelMapMesh3 meshes them, each region keeping its label).
  std::map<int, vtkIdType> voxelsOf; // own label -> voxel count
  if (!amInputCheck::LabelCounts(scalars, -amInputCheck::LargestLabel, amInputCheck::LargestLabel, voxelsOf, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  if (!amInputCheck::LabelCount(voxelsOf.size() - voxelsOf.count(bg), why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  if (voxelsOf.size() == 1 && voxelsOf.begin()->first == bg)
  {
    vtkErrorMacro("The label map holds only the background label " << bg << ": nothing to mesh.");
    return 0;
  }
  amLabelMapMesh3::Settings settings;
  settings.Background = bg;
  settings.FacetDistance = this->FacetDistance;
  settings.FacetSize = this->FacetSize;
  settings.FacetAngle = this->FacetAngle;
  settings.CellSize = this->CellSize;
  settings.CellRadiusEdgeRatio = this->CellRadiusEdgeRatio;
  settings.ProtectJunctions = this->ProtectJunctions != 0;
  settings.EdgeSize = this->EdgeSize;
  settings.Odt = this->Odt != 0;
  settings.Lloyd = this->Lloyd != 0;
  settings.Perturb = this->Perturb != 0;
  settings.Exude = this->Exude != 0;
  settings.SliverBound = this->SliverBound;
  settings.RegionCellSizes = this->RegionCellSizes;
  settings.Progress = [this](double f) { this->UpdateProgress(f); };
  const amLabelMapMesh3::Grid grid{ { dims[0], dims[1], dims[2] }, { spacing[0], spacing[1], spacing[2] },
    { origin[0], origin[1], origin[2] }, direction };
  amLabelMapMesh3::Result meshed;
  if (!amLabelMapMesh3::Mesh(scalars, grid, voxelsOf, settings, output, interfaces, meshed, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  for (const auto& warning : meshed.Warnings)
    vtkWarningMacro(<< warning);
  const double edgeSize = meshed.EdgeSize;
  const std::size_t curves = meshed.Curves;

  std::map<int, double> voxelVolumes; // label -> mm^3: the correction's targets and the report's reference
  for (const auto& lv : voxelsOf)
    if (lv.first != bg)
      voxelVolumes[lv.first] = lv.second * spacing[0] * spacing[1] * spacing[2];
  vtkNew<vtkDoubleArray> voxels;
  voxels->SetNumberOfComponents(2);
  for (const auto& lv : voxelVolumes)
  {
    const double row[2] = { static_cast<double>(lv.first), lv.second };
    voxels->InsertNextTuple(row);
  }
  // The improvement (and the volume correction) as amTetrahedralize finishes its mesh.
  const bool improve = this->ImproveQuality && this->ImprovementPasses > 0;
  amTetraFinish::Settings finish;
  finish.Improve = improve || this->PreserveVolumes;
  finish.Options.Passes = improve ? this->ImprovementPasses : 0;
  finish.Options.MaximumSurfaceDeviation = improve ? this->MaximumSurfaceDeviation : 0;
  if (this->PreserveVolumes)
  {
    finish.Options.TargetVolumes = voxelVolumes;
    // The voxels' staircase lies up to half a voxel from any smooth surface through them: the
    // surface may move that far, or FacetDistance where that is more.
    finish.Options.MaximumVolumeOffset =
      std::max(this->FacetDistance, 0.5 * std::max({ spacing[0], spacing[1], spacing[2] }));
  }
  finish.VoxelVolumes = voxels;
  finish.Remedy = "Smaller FacetSize, FacetDistance or CellSize, or a larger MaximumSurfaceDeviation, frees them.";
  finish.Progress = [this](double f) { this->UpdateProgress(0.92 + 0.08 * f); };
  amTetraFinish::Result finished;
  if (!amTetraFinish::Run(output, interfaces, finish, finished, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  this->SurfaceDeviation = finished.Report.SurfaceDeviation;
  this->VolumeDisplacement = finished.Report.VolumeDisplacement;
  this->NumberOfSlivers = finished.Poor;
  this->NumberOfVolumeMisses = static_cast<vtkIdType>(finished.VolumeMisses.size());
  if (!finished.VolumeWarning.empty())
    vtkWarningMacro(<< finished.VolumeWarning);
  this->NumberOfTetrahedra = output->GetNumberOfCells();
  if (!finished.BarWarning.empty())
    vtkWarningMacro(<< finished.BarWarning);
  std::ostringstream params;
  params << "FacetDistance=" << this->FacetDistance << " FacetSize=" << this->FacetSize
         << " FacetAngle=" << this->FacetAngle << " CellSize=" << this->CellSize
         << " CellRadiusEdgeRatio=" << this->CellRadiusEdgeRatio << " ProtectJunctions=" << this->ProtectJunctions
         << " EdgeSize=" << edgeSize << " curves=" << curves << " Odt=" << this->Odt << " Lloyd=" << this->Lloyd
         << " Perturb=" << this->Perturb << " Exude=" << this->Exude << " SliverBound=" << this->SliverBound
         << " PreserveVolumes=" << this->PreserveVolumes << " ImproveQuality=" << this->ImproveQuality
         << " ImprovementPasses=" << this->ImprovementPasses
         << " MaximumSurfaceDeviation=" << this->MaximumSurfaceDeviation << " tetrahedra=" << this->NumberOfTetrahedra
         << finished.Describe();
  for (std::size_t k = 0; k + 1 < this->RegionCellSizes.size(); k += 2)
    params << (k ? "," : " RegionCellSizes=") << this->RegionCellSizes[k] << "," << this->RegionCellSizes[k + 1];
  amProvenance::Record(output, input, "amLabelMapTetrahedralize", params.str());
  amProvenance::Record(interfaces, input, "amLabelMapTetrahedralize", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amLabelMapTetrahedralize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundLabel: " << this->BackgroundLabel << "\n"
     << indent << "FacetDistance: " << this->FacetDistance << "\n"
     << indent << "FacetSize: " << this->FacetSize << "\n"
     << indent << "FacetAngle: " << this->FacetAngle << "\n"
     << indent << "CellSize: " << this->CellSize << "\n"
     << indent << "CellRadiusEdgeRatio: " << this->CellRadiusEdgeRatio << "\n"
     << indent << "RegionCellSizes: " << this->RegionCellSizes.size() / 2 << " region(s)\n"
     << indent << "ProtectJunctions: " << this->ProtectJunctions << "\n"
     << indent << "EdgeSize: " << this->EdgeSize << "\n"
     << indent << "Odt: " << this->Odt << " Lloyd: " << this->Lloyd << " Perturb: " << this->Perturb
     << " Exude: " << this->Exude << "\n"
     << indent << "SliverBound: " << this->SliverBound << "\n"
     << indent << "PreserveVolumes: " << this->PreserveVolumes << "\n"
     << indent << "ImproveQuality: " << this->ImproveQuality << " ImprovementPasses: " << this->ImprovementPasses
     << " MaximumSurfaceDeviation: " << this->MaximumSurfaceDeviation << "\n";
}
