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

long long MarkNearFarTriangles(const Remesher& remeshed, vtkStaticPointLocator* input, std::vector<unsigned char>& keep)
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
    const double reach = longest + eps;
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

std::shared_ptr<Remesher> RemeshKeepingTheBound(amSurfaceMesh& surface, const std::vector<Mat3>& metric,
  const KeepInputRun& options, Remesher::Result& result, long long& kept)
{
  auto setup = [&options, &metric](const amSurfaceMesh& input, const std::vector<unsigned char>* held) {
    auto remesher = std::make_shared<Remesher>();
    remesher->Setup(input, metric, options.Tolerance);
    remesher->KeepVolumes = options.KeepVolumes;
    if (held)
    {
      remesher->Mesh.Held.assign(held->begin(), held->end());
      remesher->RoundVolumeOffsets = true;
    }
    return remesher;
  };
  auto run = [&options](Remesher& remesher, double start, double span) {
    return remesher.Run(options.Iterations, [&](double fraction) {
      if (options.Progress)
        options.Progress(start + span * fraction);
    });
  };
  std::shared_ptr<Remesher> remesher = setup(surface, nullptr);
  surface = amSurfaceMesh();
  result = run(*remesher, 0.05, 0.45);
  kept = 0;
  if (!(result.Hausdorff > options.Tolerance) || !options.Rebuild || !options.Rebuild(surface))
    return remesher;
  // Each run holds the input vertices near the far triangles of every run before it: held, the
  // input's triangles there stay as they are (distance 0). A held region changes the volumes the
  // rest of the run corrects (rounded in these runs, so that they move the rest alike), and the
  // next run can end beyond the bound somewhere else: the runs go on (at most RerunsAtMost) until
  // one keeps the bound, else the closest is taken.
  std::vector<unsigned char> keep(surface.Points.size(), 0);
  const vtkSmartPointer<vtkStaticPointLocator> input = InputLocator(surface.Points);
  std::shared_ptr<Remesher> last = remesher;
  for (int rerun = 0; rerun < RerunsAtMost; ++rerun)
  {
    if (MarkNearFarTriangles(*last, input, keep) == 0)
      break;
    last = setup(surface, &keep);
    const Remesher::Result again = run(*last, 0.5 + 0.45 * rerun / RerunsAtMost, 0.45 / RerunsAtMost);
    if (again.Hausdorff < result.Hausdorff)
    {
      remesher = last;
      result = again;
      kept = std::count(keep.begin(), keep.end(), 1);
    }
    if (again.Hausdorff <= options.Tolerance)
      break;
  }
  surface = amSurfaceMesh();
  return remesher;
}
}
