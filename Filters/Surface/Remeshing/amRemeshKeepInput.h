/**
 * @file    amRemeshKeepInput.h
 * @brief   Where the remeshing cannot keep its Hausdorff bound, the input's own triangles are kept:
 *          the input vertices near the triangles that end beyond the tolerance are held (Surface::Held:
 *          no operation moves or removes them, or changes a triangle of three of them) and the
 *          remeshing runs again.
 */
#ifndef amRemeshKeepInput_h
#define amRemeshKeepInput_h

#include "amRemesher.h"

#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"

#include <functional>
#include <memory>
#include <vector>

namespace amRemesh
{
/// A locator over the input surface's points, for MarkNearFarTriangles.
vtkSmartPointer<vtkStaticPointLocator> InputLocator(const std::vector<std::array<double, 3>>& points);

/// The input vertices (found by input, InputLocator's) within reach of a triangle of the remeshed
/// surface whose distance to the input exceeds the tolerance: within that triangle's longest edge
/// and the tolerance of any of its corners. Marks them in keep (sized as the input's
/// points) and returns how many it marked anew.
long long MarkNearFarTriangles(
  const Remesher& remeshed, vtkStaticPointLocator* input, std::vector<unsigned char>& keep);

/// How RemeshKeepingTheBound runs the remesher.
struct KeepInputRun
{
  double Tolerance = 0.2;
  bool KeepVolumes = true;
  int Iterations = 3;
  std::function<void(double)> Progress;        // 0..1 (may be empty)
  std::function<bool(amSurfaceMesh&)> Rebuild; // the input surface again, when a run is needed
};

/// How many times RemeshKeepingTheBound runs the remesher again at most.
constexpr int RerunsAtMost = 8;

/// Remeshes surface (emptied before the first run, to free its memory) with the metric; where the
/// result ends beyond the tolerance, runs again with the input vertices near the far triangles of
/// every run so far held (MarkNearFarTriangles), at most RerunsAtMost times, and takes the first
/// run that keeps the bound, else the closest. Returns the remesher of the result taken, with its
/// result and the number of vertices held.
std::shared_ptr<Remesher> RemeshKeepingTheBound(amSurfaceMesh& surface, const std::vector<Mat3>& metric,
  const KeepInputRun& options, Remesher::Result& result, long long& kept);

}

#endif
