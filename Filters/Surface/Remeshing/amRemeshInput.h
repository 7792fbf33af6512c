/**
 * @file    amRemeshInput.h
 * @brief   The remesher's input surface, one locator per interface (sheet), and the distance
 *          queries the approximation guard and the Hausdorff measure ask of it.
 *
 * The input never changes while the remesher works; nothing of it is copied for an undo.
 */
#ifndef amRemeshInput_h
#define amRemeshInput_h

#include "amRemeshSurface.h"
#include "amTriangleLocator.h"

#include <array>
#include <vector>

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT Input
{
public:
  std::vector<amTriangleLocator> Ref;          // per sheet: the input triangles
  std::vector<std::vector<Vec3>> Samples;      // per sheet: input vertices, edge midpoints, centroids
  std::vector<Vec3> Points;                    // the input vertices
  std::vector<std::array<int, 2>> SheetLabels; // per sheet: the labels on its two sides
  double Eps = 0.2;                            // the tolerance (mm)

  /// Locators and samples of every interface of the input (triangles with their sheets, the
  /// input's topology for its edges). Locators on one thread, samples on the other.
  void Build(const amSurfaceMesh& mesh, const std::vector<Triangle>& triangles, int nSheets);

  /// Whether x lies within Eps of the part of interface 'sheet' facing along 'normal'.
  bool Near(int sheet, const Vec3& x, const Vec3& normal) const;
  /// Edge midpoints, quarter points and centroid of a (new) triangle lie within Eps of its
  /// interface, of the part of it facing the way the triangle faces (a triangle across a thin
  /// part, nearer the other side's input, would leave far samples that no insertion can reach).
  bool TriangleNear(int sheet, const Vec3& a, const Vec3& b, const Vec3& c) const;
};
}

#endif
