/**
 * @class   amTetraGeometry
 * @brief   Small vector and tetrahedron formulas shared by the volume filters (not wrapped).
 */
#ifndef amTetraGeometry_h
#define amTetraGeometry_h

#include <array>
#include <cmath>

class amTetraGeometry
{
public:
  using Vec = std::array<double, 3>;
  static Vec Sub(const double* a, const double* b) { return { a[0] - b[0], a[1] - b[1], a[2] - b[2] }; }
  static Vec Cross(const Vec& a, const Vec& b)
  {
    return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
  }
  static double Dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static double Norm(const Vec& a) { return std::sqrt(Dot(a, a)); }

  /// Signed volume of tetrahedron (p0, p1, p2, p3): positive when p3 lies on the side of
  /// (p1 - p0) x (p2 - p0). Inline: the quality objective and the smoothing call it most.
  static double SignedVolume(const double* p0, const double* p1, const double* p2, const double* p3)
  {
    return Dot(Sub(p1, p0), Cross(Sub(p2, p0), Sub(p3, p0))) / 6.0;
  }
  /// Circumradius of the tetrahedron; +inf when it is flat.
  static double Circumradius(const double* p0, const double* p1, const double* p2, const double* p3);
};

#endif
