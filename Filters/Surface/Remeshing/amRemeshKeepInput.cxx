// Where the remeshing cannot keep its bound, the input's own triangles are kept.
#include "amRemeshKeepInput.h"

#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>

namespace amRemesh
{
vtkSmartPointer<vtkStaticPointLocator> InputLocator(const std::vector<std::array<double, 3>>& points)
{
  vtkNew<vtkPoints> cloud;
  cloud->SetDataTypeToDouble();
  cloud->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (size_t v = 0; v < points.size(); ++v)
    cloud->SetPoint(static_cast<vtkIdType>(v), points[v].data());
  vtkNew<vtkPolyData> holder;
  holder->SetPoints(cloud);
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  locator->SetDataSet(holder);
  locator->BuildLocator();
  return locator;
}

long long MarkNearFarTriangles(
  const Remesher& remeshed, vtkStaticPointLocator* input, double widen, std::vector<unsigned char>& keep)
{
  const Surface& s = remeshed.Mesh;
  const std::vector<double>& local = remeshed.Hausdorff.TriangleDistances();
  const double eps = remeshed.In.Eps;
  vtkNew<vtkIdList> found;
  long long marked = 0;
  for (size_t t = 0; t < s.T.size() && t < local.size(); ++t)
  {
    if (!s.T[t].Alive || !(local[t] > eps))
      continue;
    double longest = 0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (s.P[s.T[t].V[k]] - s.P[s.T[t].V[(k + 1) % 3]]).norm());
    const double reach = widen * (longest + eps);
    for (int k = 0; k < 3; ++k)
    {
      input->FindPointsWithinRadius(reach, s.P[s.T[t].V[k]].data(), found);
      for (vtkIdType i = 0; i < found->GetNumberOfIds(); ++i)
      {
        unsigned char& mark = keep[static_cast<size_t>(found->GetId(i))];
        marked += !mark;
        mark = 1;
      }
    }
  }
  return marked;
}

std::vector<Mat3> KeptMetric(const std::vector<Mat3>& metric, const std::vector<unsigned char>& keep, double tolerance)
{
  std::vector<Mat3> kept = metric;
  const double size = 1e-3 * tolerance;
  for (size_t v = 0; v < kept.size(); ++v)
    if (keep[v])
      kept[v] = Mat3::Identity() / (size * size);
  return kept;
}

std::shared_ptr<Remesher> RemeshKeepingTheBound(amSurfaceMesh& surface, const std::vector<Mat3>& metric,
  const KeepInputRun& options, Remesher::Result& result, long long& kept)
{
  auto setup = [&options](const amSurfaceMesh& input, std::vector<Mat3> sizes) {
    auto remesher = std::make_shared<Remesher>();
    remesher->Setup(input, std::move(sizes), options.Tolerance);
    remesher->KeepVolumes = options.KeepVolumes;
    return remesher;
  };
  auto run = [&options](Remesher& remesher, double start, double span) {
    return remesher.Run(options.Iterations, [&](double fraction) {
      if (options.Progress)
        options.Progress(start + span * fraction);
    });
  };
  std::shared_ptr<Remesher> remesher = setup(surface, metric);
  surface = amSurfaceMesh();
  result = run(*remesher, 0.05, 0.45);
  kept = 0;
  if (!(result.Hausdorff > options.Tolerance) || !options.Rebuild || !options.Rebuild(surface))
    return remesher;
  // A run is taken only when it keeps the bound: one that comes closer without keeping it changes
  // more of the surface for no guarantee.
  std::vector<unsigned char> keep(surface.Points.size(), 0);
  const vtkSmartPointer<vtkStaticPointLocator> input = InputLocator(surface.Points);
  std::shared_ptr<Remesher> last = remesher;
  for (int widen = 1; widen <= 4; ++widen)
  {
    if (MarkNearFarTriangles(*last, input, widen, keep) == 0)
      break;
    last = setup(surface, KeptMetric(metric, keep, options.Tolerance));
    const Remesher::Result again = run(*last, 0.5 + 0.1 * (widen - 1), 0.1);
    if (again.Hausdorff <= options.Tolerance)
    {
      remesher = last;
      result = again;
      kept = std::count(keep.begin(), keep.end(), 1);
      break;
    }
  }
  surface = amSurfaceMesh();
  return remesher;
}
}
