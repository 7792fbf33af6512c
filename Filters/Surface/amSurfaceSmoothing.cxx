#include "amSurfaceSmoothing.h"

#include "amProvenance.h"
#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amThreading.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(amSurfaceSmoothing);

amSurfaceSmoothing::amSurfaceSmoothing()
  : NumberOfIterations(20)
  , PassBand(0.1)
  , MaximumDisplacement(-1.0)
  , PreserveFeatures(true)
  , PreventSelfIntersections(true)
  , UsedMaximumDisplacement(0.0)
  , UntangledVertices(0)
{
  amThreading::Initialize();
}

amSurfaceSmoothing::~amSurfaceSmoothing() = default;

namespace
{
// A closed junction curve of few vertices (a loop around a voxel corner where three regions
// meet in a saddle) is held where it is: smoothed along itself, it would shrink towards a point
// (its shape is all high frequency), leaving edges of a few micrometres no remeshing can remove.
void HoldShortLoops(amSurfaceMesh& mesh)
{
  const vtkIdType np = mesh.NumberOfPoints();
  const size_t shortLoop = 12;
  std::vector<unsigned char> seen(static_cast<size_t>(np), 0);
  std::vector<vtkIdType> loop;
  for (vtkIdType v = 0; v < np; ++v)
  {
    if (seen[v] || mesh.Kind[v] != amSurfaceMesh::Curve)
      continue;
    loop.assign(1, v);
    seen[v] = 1;
    bool closed = true;
    for (size_t i = 0; i < loop.size(); ++i)
      for (vtkIdType r = mesh.RingStart[loop[i]]; r < mesh.RingStart[loop[i] + 1]; ++r)
      {
        const vtkIdType w = mesh.Ring[r];
        if (!mesh.FeatureEdge[mesh.RingEdge[r]])
          continue;
        if (mesh.Kind[w] != amSurfaceMesh::Curve)
          closed = false;
        else if (!seen[w])
        {
          seen[w] = 1;
          loop.push_back(w);
        }
      }
    if (closed && loop.size() < shortLoop)
      for (vtkIdType w : loop)
        mesh.Kind[w] = amSurfaceMesh::Corner;
  }
}

// The neighbours each vertex averages over: its whole ring, or its two curve neighbours (none for
// a corner), as lists start[v] .. start[v + 1] in nbr.
void SmoothingNeighbours(const amSurfaceMesh& mesh, std::vector<vtkIdType>& start, std::vector<vtkIdType>& nbr)
{
  const vtkIdType np = mesh.NumberOfPoints();
  start.assign(static_cast<size_t>(np + 1), 0);
  nbr.clear();
  nbr.reserve(mesh.Ring.size());
  for (vtkIdType v = 0; v < np; ++v)
  {
    if (mesh.Kind[v] == amSurfaceMesh::Surface)
      nbr.insert(nbr.end(), mesh.Ring.begin() + mesh.RingStart[v], mesh.Ring.begin() + mesh.RingStart[v + 1]);
    else if (mesh.Kind[v] == amSurfaceMesh::Curve)
      for (vtkIdType r = mesh.RingStart[v]; r < mesh.RingStart[v + 1]; ++r)
        if (mesh.FeatureEdge[mesh.RingEdge[r]])
          nbr.push_back(mesh.Ring[r]);
    start[v + 1] = static_cast<vtkIdType>(nbr.size());
  }
}

// No fold: a triangle whose normal would turn by more than 90 degrees from its input normal (x0)
// keeps its vertices where they were in this step (x), repeated until no such triangle is left.
void RevertFolds(const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& x0,
  const std::vector<std::array<double, 3>>& x, std::vector<std::array<double, 3>>& next)
{
  const vtkIdType np = mesh.NumberOfPoints();
  for (int guard = 0; guard < 10; ++guard)
  {
    std::vector<unsigned char> revert(static_cast<size_t>(np), 0);
    std::vector<unsigned char> flagged(mesh.Triangles.size(), 0);
    vtkSMPTools::For(0, mesh.NumberOfTriangles(), [&](vtkIdType t0, vtkIdType t1) {
      for (vtkIdType t = t0; t < t1; ++t)
      {
        const auto& tri = mesh.Triangles[t];
        double u[3], w[3], u0[3], w0[3];
        for (int d = 0; d < 3; ++d)
        {
          u[d] = next[tri[1]][d] - next[tri[0]][d];
          w[d] = next[tri[2]][d] - next[tri[0]][d];
          u0[d] = x0[tri[1]][d] - x0[tri[0]][d];
          w0[d] = x0[tri[2]][d] - x0[tri[0]][d];
        }
        const double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
        const double n0[3] = { u0[1] * w0[2] - u0[2] * w0[1], u0[2] * w0[0] - u0[0] * w0[2],
          u0[0] * w0[1] - u0[1] * w0[0] };
        flagged[t] = n[0] * n0[0] + n[1] * n0[1] + n[2] * n0[2] <= 0;
      }
    });
    bool any = false;
    for (vtkIdType t = 0; t < mesh.NumberOfTriangles(); ++t)
      if (flagged[t])
      {
        any = true;
        for (vtkIdType v : mesh.Triangles[t])
          revert[v] = 1;
      }
    if (!any)
      break;
    for (vtkIdType v = 0; v < np; ++v)
      if (revert[v])
        next[v] = x[v];
  }
}

}

int amSurfaceSmoothing::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  amSurfaceMesh mesh;
  std::string why;
  if (!mesh.Build(input, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  double bound = this->MaximumDisplacement;
  if (bound < 0)
  {
    vtkDataArray* voxel = input->GetFieldData()->GetArray("VoxelSize");
    // Half the voxel diagonal: the ball around a voxel corner that holds its 2x2x2 block's centres.
    bound = (voxel && voxel->GetNumberOfTuples() > 0) ? 0.5 * std::sqrt(3.0) * voxel->GetComponent(0, 0) : 0.0;
  }
  this->UsedMaximumDisplacement = bound;
  const vtkIdType np = mesh.NumberOfPoints();
  if (!this->PreserveFeatures)
    std::fill(mesh.Kind.begin(), mesh.Kind.end(), amSurfaceMesh::Surface);

  HoldShortLoops(mesh);

  std::vector<vtkIdType> start, nbr;
  SmoothingNeighbours(mesh, start, nbr);

  const double lambda = 0.5, mu = 1.0 / (this->PassBand - 1.0 / lambda);
  std::vector<std::array<double, 3>> x = mesh.Points, next(x.size());
  const std::vector<std::array<double, 3>>& x0 = mesh.Points;
  const double bound2 = bound * bound;
  for (int it = 0; it < 2 * this->NumberOfIterations; ++it)
  {
    const double f = (it % 2 == 0) ? lambda : mu;
    vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
      for (vtkIdType v = v0; v < v1; ++v)
      {
        const vtkIdType n = start[v + 1] - start[v];
        if (n == 0)
        {
          next[v] = x[v];
          continue;
        }
        double mean[3] = { 0, 0, 0 };
        for (vtkIdType r = start[v]; r < start[v + 1]; ++r)
          for (int d = 0; d < 3; ++d)
            mean[d] += x[nbr[r]][d];
        double disp[3], len2 = 0;
        for (int d = 0; d < 3; ++d)
        {
          next[v][d] = x[v][d] + f * (mean[d] / n - x[v][d]);
          disp[d] = next[v][d] - x0[v][d];
          len2 += disp[d] * disp[d];
        }
        if (bound2 > 0 && len2 > bound2)
        {
          const double s = bound / std::sqrt(len2);
          for (int d = 0; d < 3; ++d)
            next[v][d] = x0[v][d] + s * disp[d];
        }
      }
    });
    RevertFolds(mesh, x0, x, next);
    x.swap(next);
    if (it % 8 == 7)
      this->UpdateProgress(static_cast<double>(it + 1) / (2 * this->NumberOfIterations));
  }

  // Untangle: wherever triangles cross — of one region's boundary near junctions, where the ring
  // averages of several interfaces pull at each other, or of two interfaces a voxel apart, which
  // smoothing moves into each other — their vertices go back to the input, which has no
  // crossing, until none is left (each check is one CGAL box-intersection pass over the whole
  // surface, so vertices are restored at once rather than bisected).
  // The crossing test must see the coordinates that will be written: round to the input's point
  // type first (float, from amLabelSurface: rounding can fold a nearly flat pair of triangles).
  if (input->GetPoints()->GetDataType() == VTK_FLOAT)
    for (auto& p : x)
      for (double& c : p)
        c = static_cast<float>(c);
  this->UntangledVertices = 0;
  if (this->PreventSelfIntersections)
  {
    // After the first pass a crossing needs a triangle that moved back in the last round or that
    // crossed then (a pair where neither moved crossed before too), so the next pass checks only
    // those against the whole surface: the same crossings for a fraction of the work.
    bool clean = false;
    std::vector<vtkIdType> suspects;
    for (int round = 0; round < 20 && !clean; ++round)
    {
      const std::vector<vtkIdType> crossing =
        amSelfIntersection::AllTriangles(mesh, x, round == 0 ? nullptr : &suspects);
      clean = crossing.empty();
      suspects = crossing;
      for (vtkIdType t : crossing)
        for (vtkIdType v : mesh.Triangles[t])
          if (x[v] != x0[v])
          {
            x[v] = x0[v];
            ++this->UntangledVertices;
            suspects.insert(suspects.end(), mesh.VertexTriangles.begin() + mesh.VertexTriangleStart[v],
              mesh.VertexTriangles.begin() + mesh.VertexTriangleStart[v + 1]);
          }
      std::sort(suspects.begin(), suspects.end());
      suspects.erase(std::unique(suspects.begin(), suspects.end()), suspects.end());
    }
    if (!clean)
      vtkWarningMacro(<< "triangles still cross after restoring " << this->UntangledVertices
                      << " vertices to their input positions (does the input surface cross itself?)");
  }

  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(np);
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("Displacement");
  displacement->SetNumberOfTuples(np);
  vtkNew<vtkUnsignedCharArray> kind;
  kind->SetName("FeatureVertex");
  kind->SetNumberOfTuples(np);
  for (vtkIdType v = 0; v < np; ++v)
  {
    points->SetPoint(v, x[v].data());
    double d2 = 0;
    for (int d = 0; d < 3; ++d)
      d2 += (x[v][d] - x0[v][d]) * (x[v][d] - x0[v][d]);
    displacement->SetValue(v, std::sqrt(d2));
    kind->SetValue(v, mesh.Kind[v]);
  }
  output->SetPoints(points);
  output->GetPointData()->AddArray(displacement);
  output->GetPointData()->AddArray(kind);
  std::ostringstream params;
  params << "NumberOfIterations=" << this->NumberOfIterations << " PassBand=" << this->PassBand
         << " MaximumDisplacement=" << bound << " PreserveFeatures=" << this->PreserveFeatures
         << " PreventSelfIntersections=" << this->PreventSelfIntersections;
  amProvenance::Record(output, input, "amSurfaceSmoothing", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amSurfaceSmoothing::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "PassBand: " << this->PassBand << "\n";
  os << indent << "MaximumDisplacement: " << this->MaximumDisplacement << "\n";
  os << indent << "PreserveFeatures: " << this->PreserveFeatures << "\n";
}
