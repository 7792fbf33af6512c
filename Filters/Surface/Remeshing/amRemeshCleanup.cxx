#include "amRemesher.h"

#include <cmath>

namespace amRemesh
{
/// Removes triangles with an angle under 'below' where an operation that keeps the other
/// guarantees allows it: the flip of a cap's longest edge, else the collapse of the cap's apex
/// (or of the needle's short edge) into a neighbour. Caps arise where the Hausdorff insertions
/// refine along a crease of the input (the cut end of a vessel), which flips cannot cross.
/// Returns the number of operations done.
int Remesher::SmallAngleCleanup(double below)
{
  int done = 0;
  for (size_t t = 0; t < this->Mesh.T.size(); ++t)
  {
    if (!this->Mesh.T[t].Alive)
      continue;
    const int* w = this->Mesh.T[t].V;
    double angle[3];
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 u = this->Mesh.P[w[(k + 1) % 3]] - this->Mesh.P[w[k]],
                 v = this->Mesh.P[w[(k + 2) % 3]] - this->Mesh.P[w[k]];
      angle[k] = std::acos(std::max(-1.0, std::min(1.0, u.dot(v) / (u.norm() * v.norm()))));
    }
    const int small = static_cast<int>(std::min_element(angle, angle + 3) - angle);
    if (!(angle[small] < below))
      continue;
    const int large = static_cast<int>(std::max_element(angle, angle + 3) - angle);
    const int apex = w[large], a = w[(large + 1) % 3], b = w[(large + 2) % 3];
    bool ok = false;
    if (angle[large] > 0.5 * M_PI)
    {
      // A cap: its longest edge (a, b) faces the obtuse apex, which goes to the nearer end.
      const bool aNearer =
        (this->Mesh.P[apex] - this->Mesh.P[a]).norm() < (this->Mesh.P[apex] - this->Mesh.P[b]).norm();
      ok = this->Flip(std::min(a, b), std::max(a, b)) || this->Collapse(apex, aNearer ? a : b) ||
        this->Collapse(apex, aNearer ? b : a);
    }
    else
    {
      // A needle: its short edge is opposite the small angle.
      const int p = w[(small + 1) % 3], q = w[(small + 2) % 3];
      ok = this->Mesh.Kind[p] <= this->Mesh.Kind[q] ? (this->Collapse(p, q) || this->Collapse(q, p))
                                                    : (this->Collapse(q, p) || this->Collapse(p, q));
    }
    done += ok;
  }
  return done;
}
}
