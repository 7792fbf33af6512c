/**
 * @class   amTetGenParts
 * @brief   TetGen on the regions of a labelled surface in two groups at once (a child process
 *          each), put together as the result of one run.
 *
 * With the surface preserved (TetGen's Y switch), no Steiner point lies on the surface and no
 * tetrahedron spans an interface: a region's tetrahedra depend on its own boundary alone. So
 * the regions, in two groups of about equal expected work (boundary triangles, and volume over
 * the cube of the boundary's edge length), are meshed each on its own, with a TetGen hole in
 * every part of the other group, and merged: the input points first (in order, as TetGen keeps
 * them), then each group's Steiner points, the tetrahedra of every region, and each surface
 * triangle's face once, in the order of the triangles. A group whose tetrahedra do not fill its
 * regions (the surface's own volume per label, to rounding) is not trusted, nor are groups whose
 * triangles cross (each run sees its own only; CGAL's exact test runs meanwhile): the surface is
 * then meshed whole, as it is when it has one region only or is not preserved. Which regions go
 * together depends on the surface alone, never on the machine's cores.
 *
 * @sa amTetGenRun amTetraRegions amTetrahedralize
 */
#ifndef amTetGenParts_h
#define amTetGenParts_h

#include "AnatomeshFiltersVolumeModule.h" // export macro

#include "amTetGenRun.h"

#include <string>
#include <vector>

class amGradedSizeField;
class amSurfaceMesh;

class ANATOMESHFILTERSVOLUME_EXPORT amTetGenParts
{
public:
  /// Tetrahedralizes the labelled surface (regions: every label but 'background') with TetGen's
  /// switches, in two groups when 'preserved' (the switches hold Y) and there are two regions or
  /// more; "" on success, else why it failed. 'groups' (may be null) is set to the number of
  /// groups the result came from (1: one run).
  static std::string Run(const amSurfaceMesh& mesh, const amGradedSizeField& field, const std::string& switches,
    int background, bool preserved, amTetGenRun::Result& result, int* groups = nullptr);

  /// The non-background labels in two groups of about equal expected work (fewer when there
  /// are fewer labels), each sorted.
  static std::vector<std::vector<int>> Groups(const amSurfaceMesh& mesh, int background);
};

#endif
