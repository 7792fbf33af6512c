/**
 * @class   amP1Assembly
 * @brief   Mass and stiffness matrices of linear (P1) finite elements on tetrahedra, assembled
 *          on threads: the discretisation shared by the FitzHugh-Nagumo and torso solvers.
 *
 * For a tetrahedron T with volume |T| and barycentric gradients g_a:
 *   M_ab = |T| (1 + delta_ab) / 20         (consistent mass)
 *   K_ab = |T| g_a . Sigma_T g_b           (stiffness; Sigma_T the conductivity tensor of T)
 * Rows are assembled independently (each row sums its tetrahedra in a fixed order), so the
 * matrices do not depend on the thread count. Orientation does not matter; a tetrahedron whose
 * volume is below 1e-9 of its longest edge cubed (flat or collapsed), or with a non-finite
 * coordinate, is reported by FindDegenerate() and must be refused by the caller.
 */
#ifndef amP1Assembly_h
#define amP1Assembly_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <array>
#include <vector>

class amSparseMatrix;

class ANATOMESHFILTERSCORE_EXPORT amP1Assembly
{
public:
  std::vector<std::array<double, 3>> Points;
  std::vector<std::array<vtkIdType, 4>> Tetrahedra;

  /// Index of the first degenerate tetrahedron (see above), or -1.
  vtkIdType FindDegenerate() const;

  /// Assemble M and K (both get the mesh's pattern). conductivity: one symmetric tensor per
  /// tetrahedron (XX YY ZZ XY YZ XZ), or nullptr for the identity.
  void Assemble(
    const std::vector<std::array<double, 6>>* conductivity, amSparseMatrix& mass, amSparseMatrix& stiffness) const;

  /// Barycentric gradients (4 x 3) and the unsigned volume of tetrahedron t.
  void Gradients(vtkIdType t, double g[4][3], double& volume) const;

  /// Conductivity tensor sigma_t I + (sigma_l - sigma_t) f f^T for a unit fiber f (f may be zero:
  /// isotropic sigma_l).
  static std::array<double, 6> FiberTensor(double sigmaL, double sigmaT, const double f[3]);
};

#endif
