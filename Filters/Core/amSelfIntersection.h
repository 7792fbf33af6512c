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

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <array>
#include <vector>

class amSurfaceMesh;

class ANATOMESHFILTERSCORE_EXPORT amSelfIntersection
{
public:
  /// Sorted vertex ids of all triangles involved in a crossing, using the given positions.
  static std::vector<vtkIdType> Vertices(
    const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points, int background = 0);
  /// Sorted indices of the triangles involved in a crossing.
  static std::vector<vtkIdType> Triangles(
    const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points, int background = 0);

  /// Sorted indices of the triangles that cross any other triangle of the whole surface, whatever
  /// their regions (two organs' boundaries running through each other are found too).
  static std::vector<vtkIdType> AllTriangles(
    const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points);
  /// The same for the crossings that involve one of the triangles 'among' (any order; nullptr:
  /// all): each of them against the whole surface, both triangles of a crossing pair returned.
  static std::vector<vtkIdType> AllTriangles(
    const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points, const std::vector<vtkIdType>* among);

  /// Exact test (CGAL's filtered predicates): do triangles a and b, with vertex ids ia and ib,
  /// meet anywhere other than in the vertices and edge they share? Identical vertex sets count
  /// as crossing; so do two triangles on one edge folded flat onto each other.
  static bool Cross(const double* const a[3], const vtkIdType ia[3], const double* const b[3], const vtkIdType ib[3]);
};

#endif
