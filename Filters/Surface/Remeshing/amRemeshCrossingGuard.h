/**
 * @file    amRemeshCrossingGuard.h
 * @brief   The remesher's guard against self-intersection: would an operation's new triangles
 *          cross a live triangle, or each other?
 *
 * Every collapse, flip, move, split and insertion asks before it changes anything, so the
 * remesher's output never intersects itself (TetGen refuses such surfaces). Candidates come
 * from the bins; most pairs are told apart by a plane test with a margin far above rounding,
 * the rest by CGAL's exact predicates (amSelfIntersection).
 */
#ifndef amRemeshCrossingGuard_h
#define amRemeshCrossingGuard_h

#include "amRemeshBins.h"
#include "amRemeshWorker.h"

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT CrossingGuard
{
public:
  CrossingGuard(const Surface& surface, const Bins& bins)
    : S(surface)
    , B(bins)
  {
  }
  /// Would the new triangles (vertex ids and positions), replacing the triangles 'removed',
  /// cross any live triangle or each other? A new triangle with (nearly) no area, and two
  /// triangles folded flat on a shared edge (dihedral angle under ~1 degree), count as crossing.
  /// The worker's LastHit is then the live triangle in the way (-1: none of them).
  /// 'swept': the tetrahedra the moving triangles sweep on their way (a triangle whose corner
  /// moves from x0 to x1 sweeps the tetrahedron of its fixed edge, x0 and x1). A live triangle
  /// with a corner or its centroid strictly inside one was passed through: the end state may
  /// cross nothing and still enclose a region turned inside out (two opposite corners of a voxel
  /// pushed past each other), which TetGen meshes with inconsistent labels. That counts as crossing.
  bool Crosses(const std::vector<std::array<int, 3>>& ids, const std::vector<std::array<Vec3, 3>>& pos,
    const std::vector<int>& removed, Worker& worker, const std::vector<std::array<Vec3, 4>>* swept = nullptr) const;

  /// Whether x lies strictly inside the tetrahedron t (by a relative margin far above rounding;
  /// a flat tetrahedron has no inside).
  static bool StrictlyInside(const std::array<Vec3, 4>& t, const Vec3& x);

  /// Whether two triangles (ids and corners) cross or fold onto each other.
  static bool PairCrosses(
    const std::array<int, 3>& ia, const std::array<Vec3, 3>& pa, const std::array<int, 3>& ib, const Vec3* pb);
  /// Whether the vertices of q not shared with p lie strictly on one side of p's plane.
  static bool Separated(const Vec3* p, const int* ip, const Vec3* q, const int* iq);

private:
  const Surface& S;
  const Bins& B;
};
}

#endif
