#include "amMetricRemeshing.h"

#include "amProvenance.h"
#include "amRemeshKeepInput.h"
#include "amRemesher.h"
#include "amSurfaceMesh.h"
#include "amThreading.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <map>
#include <memory>
#include <sstream>
#include <utility>

vtkStandardNewMacro(amMetricRemeshing);

amMetricRemeshing::amMetricRemeshing()
  : Tolerance(0.2)
  , TargetSize(0.0)
  , NumberOfIterations(3)
  , PreserveVolumes(1)
  , Hausdorff(0)
  , HausdorffUpperBound(0)
  , InsertedPoints(0)
  , InterfacesAboveTolerance(0)
  , InputVerticesKept(0)
{
  amThreading::Initialize();
}

amMetricRemeshing::~amMetricRemeshing() = default;

int amMetricRemeshing::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using amRemesh::Mat3;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  amSurfaceMesh mesh;
  std::string why;
  if (!mesh.Build(input, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  vtkDataArray* metric = input->GetPointData()->GetArray("Metric");
  if (this->TargetSize <= 0 && (!metric || metric->GetNumberOfComponents() != 6))
  {
    vtkErrorMacro("The input has no 6-component point data \"Metric\" (run Curvature Metric first) and no "
                  "TargetSize is set.");
    return 0;
  }
  if (mesh.Labels.empty())
    for (size_t e = 0; e < mesh.Edges.size(); ++e)
      if (mesh.EdgeTriangleStart[e + 1] - mesh.EdgeTriangleStart[e] > 2)
      {
        vtkErrorMacro("The surface has a non-manifold edge (" << mesh.Edges[e][0] << ", " << mesh.Edges[e][1]
                                                              << ") and no \"Labels\" to tell its interfaces apart.");
        return 0;
      }
  // The metric per vertex: the point data (xx, yy, zz, xy, yz, xz), or the uniform TargetSize.
  const vtkIdType np = mesh.NumberOfPoints();
  std::vector<Mat3> tensors(static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
  {
    if (this->TargetSize > 0)
      tensors[v] = Mat3::Identity() / (this->TargetSize * this->TargetSize);
    else
    {
      double m[6];
      metric->GetTuple(v, m);
      tensors[v] << m[0], m[3], m[5], m[3], m[1], m[4], m[5], m[4], m[2];
      if (!tensors[v].allFinite())
      {
        vtkErrorMacro("The metric of point " << v << " is not finite.");
        return 0;
      }
    }
  }

  // The remesher keeps what it needs of the input (its points, interfaces and curves): the input's
  // topology (a quarter of the memory on a many-label input) goes before it runs.
  const bool labelled = !mesh.Labels.empty();
  const amRemesh::KeepInputRun options{ this->Tolerance, this->PreserveVolumes != 0, this->NumberOfIterations,
    [this](double fraction) { this->UpdateProgress(fraction); },
    [input](amSurfaceMesh& surface) {
      std::string unused;
      return surface.Build(input, unused);
    } };
  amRemesh::Remesher::Result result;
  long long kept = 0;
  const std::shared_ptr<amRemesh::Remesher> remesher =
    amRemesh::RemeshKeepingTheBound(mesh, tensors, options, result, kept);
  tensors.clear();
  const amRemesh::Remesher& r = *remesher;
  const double h = result.Hausdorff, upper = result.UpperBound;
  this->Hausdorff = h;
  this->HausdorffUpperBound = upper;
  this->InsertedPoints = result.Inserted;
  this->InputVerticesKept = kept;
  this->UpdateProgress(0.95);

  // Output: live vertices and triangles, labels and orientation kept.
  const amRemesh::Surface& s = r.Mesh;
  std::vector<vtkIdType> newId(s.P.size(), -1);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (size_t v = 0; v < s.P.size(); ++v)
    if (s.VAlive[v] && !s.VT[v].empty())
      newId[v] = points->InsertNextPoint(s.P[v].data());
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfComponents(2);
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("HausdorffDistance");
  const std::vector<double>& local = r.Hausdorff.TriangleDistances();
  std::map<std::pair<int, int>, double> perInterface; // (smaller label, larger) -> largest distance
  for (size_t t = 0; t < s.T.size(); ++t)
    if (s.T[t].Alive)
    {
      const amRemesh::Triangle& tri = s.T[t];
      const vtkIdType ids[3] = { newId[tri.V[0]], newId[tri.V[1]], newId[tri.V[2]] };
      polys->InsertNextCell(3, ids);
      labels->InsertNextTypedTuple(tri.Labels);
      const double d = t < local.size() ? local[t] : 0.0;
      distance->InsertNextValue(d);
      double& worst = perInterface[std::minmax(tri.Labels[0], tri.Labels[1])];
      worst = std::max(worst, d);
    }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetFieldData()->PassData(input->GetFieldData());
  output->GetCellData()->AddArray(distance);
  if (labelled)
  {
    output->GetCellData()->AddArray(labels);
    // Per interface (lower label, higher label, its largest distance): where the bound is missed
    // is named, not only that it is.
    vtkNew<vtkDoubleArray> interfaces;
    interfaces->SetName("InterfaceHausdorff");
    interfaces->SetNumberOfComponents(3);
    std::ostringstream missed;
    this->InterfacesAboveTolerance = 0;
    for (const auto& [pair, d] : perInterface)
    {
      const double row[3] = { static_cast<double>(pair.first), static_cast<double>(pair.second), d };
      interfaces->InsertNextTuple(row);
      if (d > this->Tolerance && this->InterfacesAboveTolerance++ < 10)
        missed << (this->InterfacesAboveTolerance > 1 ? ", " : "") << pair.first << "|" << pair.second << " " << d
               << " mm";
    }
    output->GetFieldData()->AddArray(interfaces);
    if (this->InterfacesAboveTolerance > 0)
      vtkWarningMacro("The Hausdorff distance to the input is "
        << h << " mm, above the tolerance " << this->Tolerance << " mm on " << this->InterfacesAboveTolerance
        << " interface(s) (" << missed.str() << (this->InterfacesAboveTolerance > 10 ? ", ..." : "")
        << "): refining further would make triangles cross (where interfaces meet at a small angle or a part is "
           "thinner than the tolerance).");
  }
  else if (h > this->Tolerance)
  {
    this->InterfacesAboveTolerance = 1;
    vtkWarningMacro("The Hausdorff distance to the input is " << h << " mm, above the tolerance " << this->Tolerance
                                                              << " mm: refining further would make triangles cross.");
  }
  // The tolerance asked for travels with the surface: the tetrahedra's default surface deviation follows it.
  for (const auto& f : { std::make_pair("Hausdorff", h), std::make_pair("HausdorffUpperBound", upper),
         std::make_pair("Tolerance", this->Tolerance) })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(f.first);
    a->InsertNextValue(f.second);
    output->GetFieldData()->AddArray(a);
  }
  std::ostringstream params;
  params << "Tolerance=" << this->Tolerance << " TargetSize=" << this->TargetSize
         << " NumberOfIterations=" << this->NumberOfIterations << " PreserveVolumes=" << this->PreserveVolumes
         << " Hausdorff=" << h << " InsertedPoints=" << result.Inserted << " InputVerticesKept=" << kept
         << " Collapses=" << r.Collapses() << " Flips=" << r.Flips() << " Moves=" << r.Moves();
  amProvenance::Record(output, input, "amMetricRemeshing", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amMetricRemeshing::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "TargetSize: " << this->TargetSize << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "PreserveVolumes: " << this->PreserveVolumes << "\n";
}
