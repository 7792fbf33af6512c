/**
 * @class   amSelfIntersection
 * @brief   The vertices of the triangles that cross other triangles of the same region's boundary
 *          (CGAL's exact self-intersection test), for a labelled multi-material surface.
 *
 * Each region (every label of the 2-component "Labels" cell data except the background) is
 * checked on its own closed boundary. Regions whose boundary is not a manifold polygon mesh are
 * skipped (amSurfaceTopology reports those). Kept in its own translation unit: CGAL is heavy.
 */
#ifndef amSelfIntersection_h
#define amSelfIntersection_h

#include "vtkType.h"

#include <array>
#include <vector>

class amSurfaceMesh;

class amSelfIntersection
{
public:
  /// Sorted vertex ids of all triangles involved in a crossing, using the given positions.
  static std::vector<vtkIdType> Vertices(const amSurfaceMesh& mesh,
    const std::vector<std::array<double, 3>>& points, int background = 0);
  /// Sorted indices of the triangles involved in a crossing.
  static std::vector<vtkIdType> Triangles(const amSurfaceMesh& mesh,
    const std::vector<std::array<double, 3>>& points, int background = 0);
};

#endif
