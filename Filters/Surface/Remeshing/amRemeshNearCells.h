/**
 * @file    amRemeshNearCells.h
 * @brief   A coarse grid over a set of points, its cells flagged where they come within Reach of
 *          a triangle of a set: a point whose cell is not flagged is farther than Reach from all.
 *
 * The Hausdorff measure queries again only the input samples near a changed triangle.
 */
#ifndef amRemeshNearCells_h
#define amRemeshNearCells_h

#include "amRemeshSurface.h"

#include "vtkType.h"

#include <array>
#include <vector>

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT NearCells
{
public:
  void Build(const std::vector<Vec3>& points, double reach, const std::vector<std::array<double, 3>>& pts,
    const std::vector<std::array<vtkIdType, 3>>& tris);
  /// Whether a point of the set, at squared distance d2 from its nearest triangle, may have one
  /// of the set's triangles nearer than that.
  bool MayComeNearer(const Vec3& x, double d2) const
  {
    if (d2 > this->Reach * this->Reach || this->Cell.empty())
      return true;
    int c[3];
    for (int d = 0; d < 3; ++d)
      c[d] = std::min(this->N[d] - 1, std::max(0, static_cast<int>((x[d] - this->Lo[d]) / this->G)));
    return this->Cell[(static_cast<size_t>(c[2]) * this->N[1] + c[1]) * this->N[0] + c[0]] != 0;
  }

private:
  double Reach = 0, G = 1;
  Vec3 Lo = Vec3::Zero();
  int N[3] = { 0, 0, 0 };
  std::vector<char> Cell;
};
}

#endif
