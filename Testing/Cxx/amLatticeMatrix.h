// A sparse symmetric positive definite matrix on a tetrahedral lattice, for the tests of the
// sparse solvers and orderings (header only).
#ifndef amLatticeMatrix_h
#define amLatticeMatrix_h

#include "amSparseMatrix.h"

#include <array>
#include <cstddef>
#include <vector>

namespace amTest
{
/// A lattice of n^3 nodes, each cube cut into six tetrahedra; the graph Laplacian plus a little of
/// the identity (symmetric positive definite), the nodes of the face x = 0 fixed.
struct LatticeMatrix
{
  amSparseMatrix A;
  std::vector<unsigned char> Fixed;

  explicit LatticeMatrix(int n)
  {
    auto id = [n](int i, int j, int k) { return static_cast<vtkIdType>((k * n + j) * n + i); };
    std::vector<std::array<vtkIdType, 4>> tets;
    for (int k = 0; k + 1 < n; ++k)
      for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
        {
          const vtkIdType c[8] = { id(i, j, k), id(i + 1, j, k), id(i, j + 1, k), id(i + 1, j + 1, k), id(i, j, k + 1),
            id(i + 1, j, k + 1), id(i, j + 1, k + 1), id(i + 1, j + 1, k + 1) };
          // Kuhn's six: the paths from corner 0 to corner 7 along the axes.
          static const int paths[6][2] = { { 1, 3 }, { 1, 5 }, { 2, 3 }, { 2, 6 }, { 4, 5 }, { 4, 6 } };
          for (const auto& p : paths)
            tets.push_back({ c[0], c[p[0]], c[p[1]], c[7] });
        }
    const vtkIdType size = static_cast<vtkIdType>(n) * n * n;
    this->A.BuildPattern(size, tets);
    for (vtkIdType r = 0; r < size; ++r)
    {
      const vtkIdType degree = this->A.RowStart[r + 1] - this->A.RowStart[r] - 1;
      for (vtkIdType k = this->A.RowStart[r]; k < this->A.RowStart[r + 1]; ++k)
        this->A.Values[k] = this->A.Columns[k] == r ? degree + 0.01 : -1.0;
    }
    this->Fixed.assign(static_cast<std::size_t>(size), 0);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        this->Fixed[id(0, j, k)] = 1;
  }
};
}

#endif
