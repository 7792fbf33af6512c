#include "amTetrahedralize.h"

#include "amGradedSizeField.h"
#include "amProvenance.h"
#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amTetGenOutput.h"
#include "amTetGenParts.h"
#include "amTetraFinish.h"
#include "amTetraGeometry.h"
#include "amTetraRegions.h"
#include "amTetraSurfaceCheck.h"
#include "amThreading.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(amTetrahedralize);

namespace
{
using Vec = amTetraGeometry::Vec;
constexpr auto Dot = &amTetraGeometry::Dot;
constexpr auto Sub = &amTetraGeometry::Sub;

// TetGen's failure in words, with the triangles that cross others, if any (whatever TetGen said;
// it may also just crash).
std::string FailureMessage(const amSurfaceMesh& mesh, const std::string& failure)
{
  std::ostringstream msg;
  msg << "Tetrahedralization failed: " << failure;
  const auto crossing = amSelfIntersection::AllTriangles(mesh, mesh.Points);
  if (!crossing.empty())
    msg << " The surface intersects itself: " << crossing.size()
        << " triangles cross others: " << amTetraSurfaceCheck::List(crossing) << ".";
  return msg.str();
}

// The mesh size at each surface point: the sizing array's (positive, or false with 'why' naming
// the point), else the mean length of the point's edges.
bool SurfaceSizes(const amSurfaceMesh& mesh, vtkDataArray* sizeArray, std::vector<double>& sizes, std::string& why)
{
  const vtkIdType np = mesh.NumberOfPoints();
  sizes.assign(static_cast<size_t>(np), 0.0);
  if (sizeArray)
  {
    for (vtkIdType v = 0; v < np; ++v)
    {
      sizes[v] = sizeArray->GetComponent(v, 0);
      if (!std::isfinite(sizes[v]) || sizes[v] <= 0)
      {
        std::ostringstream message;
        message << "is " << sizes[v] << " at point " << v << ": sizes must be positive.";
        why = message.str();
        return false;
      }
    }
    return true;
  }
  for (vtkIdType v = 0; v < np; ++v)
  {
    double sum = 0;
    const vtkIdType k0 = mesh.RingStart[v], k1 = mesh.RingStart[v + 1];
    for (vtkIdType k = k0; k < k1; ++k)
    {
      const Vec d = Sub(mesh.Points[mesh.Ring[k]].data(), mesh.Points[v].data());
      sum += std::sqrt(Dot(d, d));
    }
    sizes[v] = k1 > k0 ? sum / static_cast<double>(k1 - k0) : 0.0;
  }
  return true;
}
}

amTetrahedralize::amTetrahedralize()
  : BackgroundLabel(0)
  , PreserveSurface(1)
  , ParallelGroups(false)
  , MaximumRadiusEdgeRatio(1.5)
  , MinimumDihedralAngle(12.0)
  , Gradation(1.3)
  , MaximumSize(0.0)
  , SizeArrayName(nullptr)
  , OptimizationLevel(3)
  , ImproveQuality(1)
  , ImprovementPasses(4)
  , MaximumSurfaceDeviation(-1.0)
  , NumberOfTetrahedra(0)
  , NumberOfSteinerPoints(0)
  , WorstQualityBeforeImprovement(0)
  , MeanQualityBeforeImprovement(0)
  , SurfaceDeviation(0)
  , NumberOfSlivers(0)
  , NumberOfVolumeMisses(0)
  , NumberOfGroups(0)
{
  this->SetSizeArrayName("Size");
  this->SetNumberOfOutputPorts(2);
  amThreading::Initialize();
}

amTetrahedralize::~amTetrahedralize()
{
  this->SetSizeArrayName(nullptr);
}

int amTetrahedralize::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int amTetrahedralize::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int amTetrahedralize::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* interfaces = vtkPolyData::GetData(outputVector, 1);
  this->NumberOfTetrahedra = 0;
  this->NumberOfSteinerPoints = 0;
  this->NumberOfGroups = 0;
  const int bg = this->BackgroundLabel;

  // --- Input checks ------------------------------------------------------------------------------
  amSurfaceMesh mesh;
  std::string why;
  if (!input || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The input surface is empty: no triangles to mesh.");
    return 0;
  }
  if (!mesh.Build(input, why))
  {
    vtkErrorMacro("Input surface: " << why);
    return 0;
  }
  const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
  if (!amTetraSurfaceCheck::Check(input, mesh, bg, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  this->UpdateProgress(0.05);

  // --- Sizes ---------------------------------------------------------------------------------------
  std::vector<double> sizes;
  vtkDataArray* sizeArray =
    this->SizeArrayName && *this->SizeArrayName ? input->GetPointData()->GetArray(this->SizeArrayName) : nullptr;
  if (!SurfaceSizes(mesh, sizeArray && sizeArray->GetNumberOfComponents() == 1 ? sizeArray : nullptr, sizes, why))
  {
    vtkErrorMacro("The sizing array \"" << this->SizeArrayName << "\" " << why);
    return 0;
  }
  double bounds[6];
  input->GetBounds(bounds);
  amGradedSizeField field;
  if (!field.Build(mesh.Points, sizes, this->Gradation, this->MaximumSize, bounds, why))
  {
    vtkErrorMacro("Sizing: " << why);
    return 0;
  }
  this->UpdateProgress(0.1);

  // --- TetGen --------------------------------------------------------------------------------------
  std::ostringstream sw;
  sw << "pzQnM" << (this->PreserveSurface ? "Y" : "") << "q" << this->MaximumRadiusEdgeRatio << "/"
     << this->MinimumDihedralAngle << "O" << this->OptimizationLevel << "/7";
  const std::string switches = sw.str();
  amTetGenRun::Result out;
  const std::string failure = amTetGenParts::Run(
    mesh, field, switches, bg, this->PreserveSurface && this->ParallelGroups, out, &this->NumberOfGroups);
  if (!failure.empty())
  {
    vtkErrorMacro(<< FailureMessage(mesh, failure));
    return 0;
  }
  this->UpdateProgress(0.8);

  const vtkIdType nOutPoints = out.NumberOfPoints, nTets = out.NumberOfTetrahedra, nSub = out.NumberOfFaces;
  if (nTets == 0)
  {
    vtkErrorMacro("TetGen produced no tetrahedra.");
    return 0;
  }
  if (this->PreserveSurface)
  {
    bool same = nOutPoints >= np && nSub == nt;
    for (vtkIdType v = 0; same && v < np; ++v)
      for (int d = 0; d < 3; ++d)
        same = same && out.Points[3 * v + d] == mesh.Points[v][d];
    if (!same)
    {
      vtkErrorMacro(
        "TetGen did not keep the input surface (" << nSub << " boundary triangles for " << nt << " input triangles).");
      return 0;
    }
  }

  // --- Regions ------------------------------------------------------------------------------------
  amTetraRegions regions;
  if (!regions.Assign(mesh, out, bg, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  this->UpdateProgress(0.9);

  // --- Output --------------------------------------------------------------------------------------
  if (!amTetGenOutput::Build(mesh, out, regions, bg, output, interfaces, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  this->UpdateProgress(0.92);

  // The surface may move half the tolerance it was remeshed to, unless a deviation is set.
  this->SurfaceDeviationUsed = this->MaximumSurfaceDeviation;
  if (this->SurfaceDeviationUsed < 0)
  {
    vtkDataArray* tolerance = input->GetFieldData()->GetArray("Tolerance");
    this->SurfaceDeviationUsed = tolerance && tolerance->GetNumberOfTuples() > 0 && tolerance->GetComponent(0, 0) > 0
      ? 0.5 * tolerance->GetComponent(0, 0)
      : 0.2;
  }

  // --- Quality improvement, region volumes, element bars -------------------------------------------
  // Flips and smoothing inside the regions; the surface moves only to free slivers. Each region's
  // volume is compared with its label's voxels when the surface carries them (from amLabelSurface).
  amTetraFinish::Settings finish;
  finish.Improve = this->ImproveQuality && this->ImprovementPasses > 0;
  finish.Options.Passes = this->ImprovementPasses;
  finish.Options.MaximumSurfaceDeviation = this->SurfaceDeviationUsed;
  finish.VoxelVolumes = input->GetFieldData()->GetArray("LabelVoxelVolumes");
  finish.Remedy =
    "A finer surface (a smaller TargetSize or Tolerance upstream) or a larger MaximumSurfaceDeviation frees them.";
  finish.Progress = [this](double f) { this->UpdateProgress(0.92 + 0.08 * f); };
  amTetraFinish::Result finished;
  if (!amTetraFinish::Run(output, interfaces, finish, finished, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  this->WorstQualityBeforeImprovement = finished.Report.WorstBefore;
  this->MeanQualityBeforeImprovement = finished.Report.MeanBefore;
  this->SurfaceDeviation = finished.Report.SurfaceDeviation;
  this->NumberOfSlivers = finished.Poor;
  this->NumberOfVolumeMisses = static_cast<vtkIdType>(finished.VolumeMisses.size());
  if (!finished.VolumeWarning.empty())
    vtkWarningMacro(<< finished.VolumeWarning);
  this->NumberOfTetrahedra = output->GetNumberOfCells();
  this->NumberOfSteinerPoints = output->GetNumberOfPoints() - np;
  if (!finished.BarWarning.empty())
    vtkWarningMacro(<< finished.BarWarning);
  std::ostringstream params;
  params << "switches=" << switches << " Gradation=" << this->Gradation << " MaximumSize=" << this->MaximumSize
         << " ImproveQuality=" << this->ImproveQuality << " ImprovementPasses=" << this->ImprovementPasses
         << " MaximumSurfaceDeviation=" << this->SurfaceDeviationUsed << " groups=" << this->NumberOfGroups
         << " tetrahedra=" << this->NumberOfTetrahedra << finished.Describe();
  amProvenance::Record(output, input, "amTetrahedralize", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amTetrahedralize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundLabel: " << this->BackgroundLabel << "\n";
  os << indent << "PreserveSurface: " << this->PreserveSurface << "\n";
  os << indent << "ParallelGroups: " << this->ParallelGroups << "\n";
  os << indent << "MaximumRadiusEdgeRatio: " << this->MaximumRadiusEdgeRatio << "\n";
  os << indent << "MinimumDihedralAngle: " << this->MinimumDihedralAngle << "\n";
  os << indent << "Gradation: " << this->Gradation << "\n";
  os << indent << "MaximumSize: " << this->MaximumSize << "\n";
  os << indent << "SizeArrayName: " << (this->SizeArrayName ? this->SizeArrayName : "(none)") << "\n";
  os << indent << "OptimizationLevel: " << this->OptimizationLevel << "\n";
  os << indent << "MaximumSurfaceDeviation: " << this->MaximumSurfaceDeviation << "\n";
  os << indent << "ImproveQuality: " << this->ImproveQuality << "\n";
  os << indent << "ImprovementPasses: " << this->ImprovementPasses << "\n";
}
