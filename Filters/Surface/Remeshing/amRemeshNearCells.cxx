#include "amRemeshNearCells.h"

#include <limits>

namespace amRemesh
{
void NearCells::Build(const std::vector<Vec3>& points, double reach, const std::vector<std::array<double, 3>>& pts,
  const std::vector<std::array<vtkIdType, 3>>& tris)
{
  this->Reach = reach;
  this->Lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -this->Lo;
  for (const Vec3& x : points)
  {
    this->Lo = this->Lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  if (points.empty())
    return;
  // Cells at least twice the reach, at most 64 along the longest side (a few hundred thousand
  // bytes per interface, cleared at every measure).
  this->G = std::max({ 2.0 * reach, (hi - this->Lo).maxCoeff() / 64.0, 1e-9 });
  for (int d = 0; d < 3; ++d)
    this->N[d] = static_cast<int>((hi[d] - this->Lo[d]) / this->G) + 1;
  this->Cell.assign(static_cast<size_t>(this->N[0]) * this->N[1] * this->N[2], 0);
  for (const auto& t : tris)
  {
    int lo[3], up[3];
    for (int d = 0; d < 3; ++d)
    {
      const double a = std::min({ pts[t[0]][d], pts[t[1]][d], pts[t[2]][d] }) - reach,
                   b = std::max({ pts[t[0]][d], pts[t[1]][d], pts[t[2]][d] }) + reach;
      lo[d] = std::max(0, static_cast<int>(std::floor((a - this->Lo[d]) / this->G)));
      up[d] = std::min(this->N[d] - 1, static_cast<int>(std::floor((b - this->Lo[d]) / this->G)));
    }
    for (int k = lo[2]; k <= up[2]; ++k)
      for (int j = lo[1]; j <= up[1]; ++j)
        for (int i = lo[0]; i <= up[0]; ++i)
          this->Cell[(static_cast<size_t>(k) * this->N[1] + j) * this->N[0] + i] = 1;
  }
}
}
