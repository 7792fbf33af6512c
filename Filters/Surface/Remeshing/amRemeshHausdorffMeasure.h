/**
 * @file    amRemeshHausdorffMeasure.h
 * @brief   The two-sided (Hausdorff) distance between the remesher's surface and its input, per
 *          interface, with the points to insert where it exceeds the tolerance.
 *
 * Input -> result: every input sample (vertices, edge midpoints, centroids) to the nearest result
 * triangle of its interface, or where that is farther than the tolerance, to the farther of its
 * two regions' boundaries (where an interface narrows to a junction curve, the regions still meet
 * within the tolerance although no triangle of theirs does). Result -> input: a grid of points
 * on every result triangle (spacing at most the tolerance, at most 12 intervals per edge), after
 * its centroid and edge midpoints; the grid's gap enters the upper bound. A later measure
 * measures again only what changed since the last one: the input is fixed, so a triangle with
 * the same vertices at the same places has the same distances, and an input sample whose
 * nearest triangle is unchanged can only have come nearer to a new one.
 */
#ifndef amRemeshHausdorffMeasure_h
#define amRemeshHausdorffMeasure_h

#include "amRemeshInput.h"

#include <map>
#include <utility>
#include <vector>

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT HausdorffMeasure
{
public:
  /// The Hausdorff distance of the surface to the input (the largest sampled distance); its
  /// upper bound (with the sampling gap) into upperBound; the triangles to refine, each with the
  /// input point farthest from it, into insert, and the edge that point's sample lies on (-1:
  /// inside) into edgeOf.
  double Measure(const Surface& surface, const amRemesh::Input& input, double& upperBound,
    std::vector<std::pair<int, Vec3>>& insert, std::vector<int>& edgeOf);

  /// Per triangle slot, at the last Measure: the largest distance measured on it (its samples to
  /// the input, and the input samples whose nearest triangle it is), mm; 0 for dead slots.
  const std::vector<double>& TriangleDistances() const { return this->Local; }
  /// Back to the distances of an earlier state (the remesher restoring a surface it saved).
  void RestoreTriangleDistances(std::vector<double>&& local) { this->Local = std::move(local); }
  /// Forgets what the last Measure saw (the surface's vertices and slots were renumbered): the
  /// next Measure measures everything.
  void Forget()
  {
    this->Cache = MeasureCache();
    this->Local.clear();
  }

private:
  std::vector<double> Local;
  /// The farther of the distances (squared) from x to the boundaries of the two regions of
  /// 'sheet' (any triangle with the label on a side), inf where a region has none.
  double ToBothRegions(const Surface& surface, const std::vector<std::array<double, 3>>& points,
    const amRemesh::Input& input, int sheet, const Vec3& x);
  std::map<int, amTriangleLocator> Regions; // per label: its region's boundary, this Measure ...
  std::map<int, std::vector<std::array<vtkIdType, 3>>> RegionTriangles; // ... and its triangles

  // What the last Measure saw.
  struct MeasureCache
  {
    bool Valid = false;
    std::vector<std::array<int, 4>> Tri; // per triangle slot: vertices and sheet (sheet -1: dead)
    std::vector<Vec3> P;                 // vertex positions
    std::vector<double> Worst, Gap;      // per triangle slot: remeshed -> input
    std::vector<Vec3> Far;
    std::vector<int> Edge;
    std::vector<std::vector<double>> D2; // per sheet, per input sample: squared distance ...
    std::vector<std::vector<int>> At;    // ... and the nearest triangle's slot (-1: none)
  } Cache;
  /// Whether triangle slot t is as the last Measure saw it.
  bool Unchanged(const Surface& surface, size_t t) const;
};
}

#endif
