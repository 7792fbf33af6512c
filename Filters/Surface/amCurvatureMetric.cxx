#include "amCurvatureMetric.h"

#include "amProvenance.h"
#include "amSurfaceCurvature.h"
#include "amSurfaceMesh.h"
#include "amThreading.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <sstream>

vtkStandardNewMacro(amCurvatureMetric);

amCurvatureMetric::amCurvatureMetric()
  : Tolerance(0.2)
  , MinimumSize(0.5)
  , MaximumSize(20.0)
  , Gradation(1.3)
  , Anisotropic(true)
  , NeighborhoodRings(2)
  , NeighborhoodRadius(0.0)
  , ScaleAdaptive(true)
{
  amThreading::Initialize();
}

amCurvatureMetric::~amCurvatureMetric() = default;

int amCurvatureMetric::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (this->MinimumSize > this->MaximumSize)
  {
    vtkErrorMacro("MinimumSize " << this->MinimumSize << " mm exceeds MaximumSize " << this->MaximumSize << " mm.");
    return 0;
  }
  amSurfaceMesh mesh;
  std::string why;
  if (!mesh.Build(input, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  const vtkIdType np = mesh.NumberOfPoints();
  // The fit's neighbourhood: every vertex of the interface within 'radius' of the vertex (reached
  // through the interface's triangles), and at least its NeighborhoodRings-ring.
  double baseRadius = this->NeighborhoodRadius;
  if (baseRadius <= 0)
  {
    vtkDataArray* voxel = input->GetFieldData()->GetArray("VoxelSize");
    baseRadius = voxel && voxel->GetNumberOfTuples() > 0 ? 2.0 * voxel->GetComponent(0, 0) : 0.0;
    if (!(baseRadius > 0))
      baseRadius = 0;
  }
  amSurfaceCurvature::Settings settings;
  settings.Radius = baseRadius;
  settings.Rings = this->NeighborhoodRings;
  settings.ScaleAdaptive = this->ScaleAdaptive;
  settings.Tolerance = this->Tolerance;
  settings.MinimumSize = this->MinimumSize;
  settings.MaximumSize = this->MaximumSize;
  const int rings = settings.Rings;
  const double eps = this->Tolerance, hmin = this->MinimumSize, hmax = this->MaximumSize;
  auto sizeOf = [&settings](double k) { return amSurfaceCurvature::Size(k, settings); };
  const std::vector<amSurfaceCurvature::Principal> curv =
    amSurfaceCurvature::Estimate(mesh, settings, [this](double f) { this->UpdateProgress(f); });
  this->UpdateProgress(0.6);

  // Sizes along the principal directions, then gradation of the smaller and of the larger one
  // (each principal size is capped by the graded field of its kind, so an anisotropic metric
  // stays anisotropic: capping both by the graded smaller size would make it isotropic).
  std::vector<double> h1(static_cast<size_t>(np)), h2(static_cast<size_t>(np)), cap(static_cast<size_t>(np)),
    capLarge(static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
  {
    h1[v] = sizeOf(curv[v].K1);
    h2[v] = sizeOf(curv[v].K2);
    if (!this->Anisotropic)
      h1[v] = h2[v] = std::min(h1[v], h2[v]);
    cap[v] = std::min(h1[v], h2[v]);
    capLarge[v] = std::max(h1[v], h2[v]);
  }
  if (this->Gradation >= 1.0)
  {
    amSurfaceCurvature::Grade(mesh, this->Gradation - 1.0, cap);
    if (this->Anisotropic) // (isotropic: both principal sizes are the smaller one, graded once)
      amSurfaceCurvature::Grade(mesh, this->Gradation - 1.0, capLarge);
  }
  this->UpdateProgress(0.8);

  output->ShallowCopy(input);
  auto make = [&](const char* name, int comps) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(comps);
    a->SetNumberOfTuples(np);
    output->GetPointData()->AddArray(a);
    return a.GetPointer();
  };
  vtkDoubleArray* metric = make("Metric", 6);
  vtkDoubleArray* size = make("Size", 1);
  vtkDoubleArray* kmax = make("MaximumCurvature", 1);
  vtkDoubleArray* kmin = make("MinimumCurvature", 1);
  vtkDoubleArray* kmean = make("MeanCurvature", 1);
  vtkDoubleArray* kgauss = make("GaussianCurvature", 1);
  vtkDoubleArray* dmax = make("MaximumDirection", 3);
  vtkDoubleArray* dmin = make("MinimumDirection", 3);
  vtkDoubleArray* normals = make("Normals", 3);
  for (vtkIdType v = 0; v < np; ++v)
  {
    const amSurfaceCurvature::Principal& c = curv[v];
    const Eigen::Map<const Eigen::Vector3d> d1(c.D1), d2(c.D2), normal(c.N);
    // The smaller principal size is capped by the graded smaller sizes, the larger by the graded
    // larger ones (isotropic: both are the smaller).
    const bool firstSmaller = h1[v] <= h2[v];
    const double a = std::min(h1[v], firstSmaller || !this->Anisotropic ? cap[v] : capLarge[v]);
    const double b = std::min(h2[v], !firstSmaller || !this->Anisotropic ? cap[v] : capLarge[v]);
    const double n = std::min(a, b);
    const Eigen::Matrix3d M =
      d1 * d1.transpose() / (a * a) + d2 * d2.transpose() / (b * b) + normal * normal.transpose() / (n * n);
    const double m[6] = { M(0, 0), M(1, 1), M(2, 2), M(0, 1), M(1, 2), M(0, 2) };
    metric->SetTypedTuple(v, m);
    size->SetValue(v, n);
    kmax->SetValue(v, c.K1);
    kmin->SetValue(v, c.K2);
    kmean->SetValue(v, 0.5 * (c.K1 + c.K2));
    kgauss->SetValue(v, c.K1 * c.K2);
    dmax->SetTypedTuple(v, c.D1);
    dmin->SetTypedTuple(v, c.D2);
    normals->SetTypedTuple(v, c.N);
  }
  std::ostringstream params;
  params << "Tolerance=" << eps << " MinimumSize=" << hmin << " MaximumSize=" << hmax
         << " Gradation=" << this->Gradation << " Anisotropic=" << this->Anisotropic << " NeighborhoodRings=" << rings
         << " NeighborhoodRadius=" << baseRadius << " ScaleAdaptive=" << this->ScaleAdaptive;
  amProvenance::Record(output, input, "amCurvatureMetric", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amCurvatureMetric::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSize: " << this->MinimumSize << "\n";
  os << indent << "MaximumSize: " << this->MaximumSize << "\n";
  os << indent << "Gradation: " << this->Gradation << "\n";
  os << indent << "Anisotropic: " << this->Anisotropic << "\n";
  os << indent << "NeighborhoodRings: " << this->NeighborhoodRings << "\n";
  os << indent << "NeighborhoodRadius: " << this->NeighborhoodRadius << "\n";
  os << indent << "ScaleAdaptive: " << this->ScaleAdaptive << "\n";
}
