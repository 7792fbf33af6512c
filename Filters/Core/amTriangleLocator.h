/**
 * @class   amTriangleLocator
 * @brief   Exact closest point on a triangle set, through a uniform grid of triangle bins.
 *
 * Queries search the grid in growing shells around the query point and stop as soon as the
 * nearest triangle found is closer than anything outside the searched box can be, so the answer
 * is exact. Queries are const and thread-safe. On surfaces where the query points lie near the
 * surface (distances, projection during remeshing) a query costs about a microsecond, one to two
 * orders of magnitude less than vtkStaticCellLocator::FindClosestPoint. Each triangle's bounding
 * sphere (about its centroid) rejects it before the exact test when it cannot be closer than the
 * best so far.
 */
#ifndef amTriangleLocator_h
#define amTriangleLocator_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <array>
#include <limits>
#include <vector>

class ANATOMESHFILTERSCORE_EXPORT amTriangleLocator
{
public:
  /// Bin the triangles (their corners are copied).
  void Build(const std::vector<std::array<double, 3>>& points, const std::vector<std::array<vtkIdType, 3>>& triangles);

  /// Closest point of the triangle set to x: returns the squared distance, sets closest and the
  /// triangle index (-1 and +inf when there is no triangle).
  double ClosestPoint(const double x[3], double closest[3], vtkIdType& triangle) const;

  /// The closest point if it is nearer than squared distance bound2 (else returns bound2 and
  /// triangle -1): only the bins within that reach are searched, so a small bound is cheap.
  double ClosestPointWithin(const double x[3], double bound2, double closest[3], vtkIdType& triangle) const;

  /// The same among the triangles whose normal (their orientation) has a positive component
  /// along 'normal': where a thin part of the surface has two sides close together, the point on
  /// the side facing the same way.
  double ClosestPointFacing(const double x[3], const double normal[3], double closest[3], vtkIdType& triangle) const;

  /// Whether some triangle lies within squared distance r2 of x (the same answer as
  /// ClosestPoint(x) <= r2, but only the bins within reach are searched and the first triangle
  /// found within reach ends the search). With 'normal', only the triangles facing that way
  /// count, as in ClosestPointFacing. 'hint' (in and out, may be null): a triangle tried
  /// first (-1: none), and the triangle found within reach (unchanged when there is none);
  /// queries at nearby points that pass on the hint mostly end at it, without a bin search.
  bool WithinDistance(const double x[3], double r2, const double* normal = nullptr, vtkIdType* hint = nullptr) const;

  /// A sphere about the centroid of (a, b, c) holding the triangle: centre and radius, the radius
  /// inflated by a relative 1e-9 so that rejections by it are safe against rounding.
  static std::array<double, 4> BoundingSphere(const double a[3], const double b[3], const double c[3]);

  /// Closest point on one triangle (a, b, c) to x; returns the squared distance.
  static double ClosestPointOnTriangle(
    const double x[3], const double a[3], const double b[3], const double c[3], double closest[3]);

private:
  double Closest(const double x[3], const double* normal, double closest[3], vtkIdType& triangle,
    double bound2 = std::numeric_limits<double>::infinity()) const;
  /// What a query reads of one triangle, in one place (two cache lines): the bounding sphere and
  /// the normal first, which reject most triangles, then the corners.
  struct alignas(64) Record
  {
    double Centre[3];
    double Radius;    // about the centroid, slightly inflated (BoundingSphere)
    double Normal[3]; // not normalised: only its sign along a query normal is used
    double Corner[3][3];
  };
  /// Whether no point of triangle t lies within distance r of x (its bounding sphere is farther).
  bool SphereBeyond(const Record& t, const double x[3], double r) const;
  /// Closest point on the triangle of a record.
  static double ClosestPointOn(const double x[3], const Record& t, double closest[3]);
  /// Whether x lies farther than sqrt(r2) from t's plane, by a relative margin far above
  /// rounding: then no point of t is that close (a cheaper test than the closest point).
  static bool PlaneBeyond(const Record& t, const double x[3], double r2)
  {
    const double* n = t.Normal;
    const double* a = t.Corner[0];
    const double d = n[0] * (x[0] - a[0]) + n[1] * (x[1] - a[1]) + n[2] * (x[2] - a[2]);
    return d * d > r2 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * (1 + 1e-9);
  }
  /// Whether the triangle's orientation has a positive component along 'normal'.
  static bool Faces(const Record& t, const double normal[3])
  {
    return t.Normal[0] * normal[0] + t.Normal[1] * normal[1] + t.Normal[2] * normal[2] > 0;
  }

  std::vector<Record> Triangles;
  double Origin[3] = { 0, 0, 0 };
  double H = 1.0;
  int N[3] = { 0, 0, 0 };
  std::vector<vtkIdType> BinStart, BinTriangles;
};

#endif
