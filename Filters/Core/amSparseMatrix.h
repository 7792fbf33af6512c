/**
 * @class   amSparseMatrix
 * @brief   Square sparse matrix in compressed-row form, with the pattern of a P1 finite-element
 *          mesh and a threaded, deterministic matrix-vector product.
 *
 * The pattern couples two nodes when they share a tetrahedron (every row holds its diagonal;
 * columns sorted). Values are filled by the assembly (amP1Assembly); Multiply() splits the rows
 * over vtkSMPTools threads, each row summed in a fixed order, so the result does not depend on
 * the thread count.
 */
#ifndef amSparseMatrix_h
#define amSparseMatrix_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <array>
#include <vector>

class ANATOMESHFILTERSCORE_EXPORT amSparseMatrix
{
public:
  /// Pattern of n nodes coupled through tetrahedra (node indices in [0, n)). Values are zero.
  void BuildPattern(vtkIdType n, const std::vector<std::array<vtkIdType, 4>>& tetrahedra);

  vtkIdType Size() const { return static_cast<vtkIdType>(this->RowStart.empty() ? 0 : this->RowStart.size() - 1); }
  vtkIdType NumberOfNonZeros() const { return static_cast<vtkIdType>(this->Columns.size()); }

  /// Position of entry (i, j) in Columns/Values, or -1 outside the pattern.
  vtkIdType Find(vtkIdType i, vtkIdType j) const;

  /// y = A x (threaded).
  void Multiply(const double* x, double* y) const;

  /// The diagonal.
  std::vector<double> Diagonal() const;

  /// this = a * A + b * B for matrices of this same pattern.
  void Combine(double a, const amSparseMatrix& A, double b, const amSparseMatrix& B);

  std::vector<vtkIdType> RowStart; // Size() + 1
  std::vector<vtkIdType> Columns;
  std::vector<double> Values;
};

#endif
