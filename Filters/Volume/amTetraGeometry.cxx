#include "amTetraGeometry.h"

#include <limits>

double amTetraGeometry::Circumradius(const double* p0, const double* p1, const double* p2, const double* p3)
{
  const Vec a = Sub(p1, p0), b = Sub(p2, p0), c = Sub(p3, p0);
  const double det = 2.0 * Dot(a, Cross(b, c)); // 12 times the signed volume
  if (det == 0.0)
    return std::numeric_limits<double>::infinity();
  const Vec bc = Cross(b, c), ca = Cross(c, a), ab = Cross(a, b);
  const double la = Dot(a, a), lb = Dot(b, b), lc = Dot(c, c);
  Vec r;
  for (int d = 0; d < 3; ++d)
    r[d] = (la * bc[d] + lb * ca[d] + lc * ab[d]) / det;
  return Norm(r);
}
