#include "amTetrahedralize.h"

#include "amGradedSizeField.h"
#include "amProvenance.h"
#include "amQualityBars.h"
#include "amRegionVolumes.h"
#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amTetGenParts.h"
#include "amTetraGeometry.h"
#include "amTetraMeshOptimizer.h"
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
constexpr auto Cross = &amTetraGeometry::Cross;
constexpr auto Dot = &amTetraGeometry::Dot;
constexpr auto Sub = &amTetraGeometry::Sub;
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
  std::vector<double> sizes(static_cast<size_t>(np), 0.0);
  vtkDataArray* sizeArray =
    this->SizeArrayName && *this->SizeArrayName ? input->GetPointData()->GetArray(this->SizeArrayName) : nullptr;
  if (sizeArray && sizeArray->GetNumberOfComponents() == 1)
  {
    for (vtkIdType v = 0; v < np; ++v)
    {
      sizes[v] = sizeArray->GetComponent(v, 0);
      if (!std::isfinite(sizes[v]) || sizes[v] <= 0)
      {
        vtkErrorMacro("The sizing array \"" << this->SizeArrayName << "\" is " << sizes[v] << " at point " << v
                                            << ": sizes must be positive.");
        return 0;
      }
    }
  }
  else
  {
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
    std::ostringstream msg;
    msg << "Tetrahedralization failed: " << failure;
    // Whatever TetGen said (it may also just crash), name triangles that cross, if any.
    const auto crossing = amSelfIntersection::AllTriangles(mesh, mesh.Points);
    if (!crossing.empty())
      msg << " The surface intersects itself: " << crossing.size()
          << " triangles cross others: " << amTetraSurfaceCheck::List(crossing) << ".";
    vtkErrorMacro(<< msg.str());
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
  const int* tets = out.Tetrahedra.data();
  const double* P = out.Points.data();
  const std::vector<std::array<vtkIdType, 2>>& subfaceTet = regions.SubfaceTet;
  auto sourceOf = [&out](vtkIdType s) { return amTetraRegions::SourceOf(out, s); };
  this->UpdateProgress(0.9);

  // --- Output --------------------------------------------------------------------------------------
  std::vector<vtkIdType> newTet(static_cast<size_t>(nTets), -1);
  std::vector<vtkIdType> newPoint(static_cast<size_t>(nOutPoints), -1);
  vtkIdType kept = 0;
  for (vtkIdType t = 0; t < nTets; ++t)
    if (regions.Label[t] != bg)
    {
      newTet[t] = kept++;
      for (int i = 0; i < 4; ++i)
        newPoint[tets[4 * t + i]] = 0;
    }
  if (kept == 0)
  {
    vtkErrorMacro("No tetrahedron lies in a region other than the background " << bg << ".");
    return 0;
  }
  // Input surface points first, in order; then the Steiner points that are used.
  vtkIdType nPoints = 0;
  for (vtkIdType v = 0; v < std::min(np, nOutPoints); ++v)
    newPoint[v] = nPoints++;
  for (vtkIdType v = np; v < nOutPoints; ++v)
    if (newPoint[v] == 0)
      newPoint[v] = nPoints++;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nPoints);
  vtkNew<vtkIdTypeArray> surfaceId;
  surfaceId->SetName("SurfacePointId");
  surfaceId->SetNumberOfTuples(nPoints);
  for (vtkIdType v = 0; v < nOutPoints; ++v)
    if (newPoint[v] >= 0)
    {
      points->SetPoint(newPoint[v], P + 3 * v);
      surfaceId->SetValue(newPoint[v], v < np ? v : -1);
    }
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(kept + 1);
  connectivity->SetNumberOfTuples(4 * kept);
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  region->SetNumberOfTuples(kept);
  for (vtkIdType t = 0; t < nTets; ++t)
  {
    const vtkIdType o = newTet[t];
    if (o < 0)
      continue;
    vtkIdType ids[4];
    for (int i = 0; i < 4; ++i)
      ids[i] = newPoint[tets[4 * t + i]];
    if (amTetraGeometry::SignedVolume(
          P + 3 * tets[4 * t], P + 3 * tets[4 * t + 1], P + 3 * tets[4 * t + 2], P + 3 * tets[4 * t + 3]) < 0)
      std::swap(ids[0], ids[1]);
    offsets->SetValue(o, 4 * o);
    for (int i = 0; i < 4; ++i)
      connectivity->SetValue(4 * o + i, ids[i]);
    region->SetValue(o, regions.Label[t]);
  }
  offsets->SetValue(kept, 4 * kept);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  output->GetCellData()->AddArray(region);
  output->GetCellData()->SetActiveScalars("Region");
  output->GetPointData()->AddArray(surfaceId);

  vtkNew<vtkCellArray> faces;
  faces->AllocateExact(nSub, 3 * nSub);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfComponents(2);
  labels->SetNumberOfTuples(nSub);
  vtkNew<vtkIdTypeArray> source, adjacent;
  source->SetName("SourceTriangle");
  source->SetNumberOfTuples(nSub);
  adjacent->SetName("Tetra");
  adjacent->SetNumberOfComponents(2);
  adjacent->SetNumberOfTuples(nSub);
  for (vtkIdType s = 0; s < nSub; ++s)
  {
    const vtkIdType src = sourceOf(s);
    vtkIdType ids[3] = { out.Faces[3 * s], out.Faces[3 * s + 1], out.Faces[3 * s + 2] };
    const auto& tri = mesh.Triangles[src];
    const Vec n0 = Cross(Sub(mesh.Points[tri[1]].data(), mesh.Points[tri[0]].data()),
      Sub(mesh.Points[tri[2]].data(), mesh.Points[tri[0]].data()));
    const Vec n1 = Cross(Sub(P + 3 * ids[1], P + 3 * ids[0]), Sub(P + 3 * ids[2], P + 3 * ids[0]));
    if (Dot(n0, n1) < 0)
      std::swap(ids[1], ids[2]);
    for (auto& id : ids)
      id = newPoint[id];
    faces->InsertNextCell(3, ids);
    labels->SetTypedTuple(s, mesh.Labels[src].data());
    source->SetValue(s, src);
    for (int k = 0; k < 2; ++k)
    {
      const vtkIdType t = subfaceTet[s][k];
      adjacent->SetComponent(s, k, t >= 0 ? static_cast<double>(newTet[t]) : -1.0);
    }
  }
  interfaces->SetPoints(points);
  interfaces->SetPolys(faces);
  interfaces->GetCellData()->AddArray(labels);
  interfaces->GetCellData()->AddArray(source);
  interfaces->GetCellData()->AddArray(adjacent);

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

  // --- Quality improvement: flips and smoothing inside the regions, the surface kept ------------
  std::ostringstream improvement;
  this->WorstQualityBeforeImprovement = this->MeanQualityBeforeImprovement = this->SurfaceDeviation = 0;
  this->NumberOfSlivers = 0;
  if (this->ImproveQuality && this->ImprovementPasses > 0)
  {
    amTetraMeshOptimizer::Options options;
    options.Passes = this->ImprovementPasses;
    options.MaximumSurfaceDeviation = this->SurfaceDeviationUsed;
    amTetraMeshOptimizer::Report report;
    if (!amTetraMeshOptimizer::ImproveGrid(
          output, interfaces, options, report, why, [this](double f) { this->UpdateProgress(0.92 + 0.08 * f); }))
    {
      vtkErrorMacro("Quality improvement: " << why);
      return 0;
    }
    this->WorstQualityBeforeImprovement = report.WorstBefore;
    this->MeanQualityBeforeImprovement = report.MeanBefore;
    this->SurfaceDeviation = report.SurfaceDeviation;
    this->NumberOfSlivers = report.Slivers;
    improvement << " improvement: " << report.Describe();
  }

  // Each region's volume against its label's voxel volume, when the surface carries them (from
  // amLabelSurface): smoothing and remeshing within their tolerances keep large organs within 2 %.
  this->NumberOfVolumeMisses = 0;
  if (vtkDataArray* voxels = input->GetFieldData()->GetArray("LabelVoxelVolumes"))
  {
    const auto misses = amRegionVolumes::Compare(output, "Region", voxels, 1000.0, 0.02);
    this->NumberOfVolumeMisses = static_cast<vtkIdType>(misses.size());
    if (!misses.empty())
      vtkWarningMacro(<< amRegionVolumes::Warning(misses));
  }

  this->NumberOfTetrahedra = output->GetNumberOfCells();
  this->NumberOfSteinerPoints = output->GetNumberOfPoints() - np;
  // Every point in a tetrahedron, and the element bars checked whatever the parameters.
  const std::string barWarning = amQualityBars::Finish(output, interfaces, this->NumberOfSlivers,
    "A finer surface (a smaller TargetSize or Tolerance upstream) or a larger MaximumSurfaceDeviation frees them.");
  if (!barWarning.empty())
    vtkWarningMacro(<< barWarning);
  std::ostringstream params;
  params << "switches=" << switches << " Gradation=" << this->Gradation << " MaximumSize=" << this->MaximumSize
         << " ImproveQuality=" << this->ImproveQuality << " ImprovementPasses=" << this->ImprovementPasses
         << " MaximumSurfaceDeviation=" << this->SurfaceDeviationUsed << " groups=" << this->NumberOfGroups
         << " tetrahedra=" << this->NumberOfTetrahedra << improvement.str();
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
