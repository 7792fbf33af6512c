/**
 * @file    amRemeshApproximationGuard.h
 * @brief   The remesher's guard of the Hausdorff bound: an operation is refused unless its new
 *          triangles stay within the tolerance of the input, and every input point that a changed
 *          vertex stands for stays within the tolerance of the result.
 *
 * Both directions of the Hausdorff distance are guarded locally, so no patch of an interface can
 * drift away from the result, retract or vanish; the HausdorffMeasure checks the whole at the end.
 */
#ifndef amRemeshApproximationGuard_h
#define amRemeshApproximationGuard_h

#include "amRemeshInput.h"
#include "amRemeshJunctionCurves.h"
#include "amRemeshWorker.h"

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT ApproximationGuard
{
public:
  ApproximationGuard(Surface& surface, const amRemesh::Input& input, const JunctionCurves& curves)
    : S(surface)
    , In(input)
    , Curves(curves)
  {
  }
  /// TriangleNear for the new triangles (ids, positions, sheets) around one vertex, 'centre' (a
  /// collapse's b, a moved vertex). Their edges away from the centre are edges of the mesh
  /// already, checked when they were made, and so are the spokes to the vertices 'kept'
  /// (sorted: those whose edge to the centre is there already, unmoved). Each other spoke is
  /// sampled once per interface, and each centroid.
  bool StarNear(const std::vector<std::array<int, 3>>& ids, const std::vector<std::array<Vec3, 3>>& pos,
    const std::vector<int>& sheets, int centre, const std::vector<int>& kept) const;
  /// Whether every input vertex that an affected vertex stands for stays within Eps of that
  /// vertex's triangles of its interface (a junction-curve point: of every interface it lies on in
  /// the input, so that no patch of an interface can vanish from around it, unless CloseStrips)
  /// once the triangles 'removed' are replaced by the new ones (ids, positions, sheets; 'newIds'
  /// the ids they will have). 'from' (or -1) is a vertex disappearing into 'into': its points are
  /// checked with into's. The hints found go to the worker's PendingHints.
  bool ClustersStayNear(const std::vector<int>& removed, const std::vector<std::array<int, 3>>& ids,
    const std::vector<std::array<Vec3, 3>>& pos, const std::vector<int>& sheets, const std::vector<int>& newIds,
    const std::vector<int>& affected, Worker& worker, int from = -1, int into = -1) const;
  /// The hints of the worker's last ClustersStayNear kept (its operation is done).
  void KeepHints(Worker& worker) const;

  /// Whether an interface may narrow to nothing between two junction curves: a junction point
  /// then passes where its two regions stay within Eps of it, though no triangle of their
  /// interface does (default off: only the small-angle cleanup closes such strips, under its
  /// undo when the Hausdorff distance grows).
  bool CloseStrips = false;

private:
  Surface& S;
  const amRemesh::Input& In;
  const JunctionCurves& Curves;
};
}

#endif
