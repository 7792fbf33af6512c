/**
 * @class   amConjugateGradient
 * @brief   Jacobi-preconditioned conjugate gradients for the symmetric positive definite systems
 *          of the P1 solvers, threaded and deterministic.
 *
 * Solves A x = b from the initial guess in x (warm starts make time stepping cheap), stopping
 * when the residual norm is at most RelativeTolerance times the norm of b (or AbsoluteTolerance,
 * whichever is larger). Nodes flagged in 'fixed' (Dirichlet nodes) keep their value in x: the
 * solve is on the free nodes, with the fixed values moved to the right-hand side, so one matrix
 * serves any set of Dirichlet data. Vector updates and products run on vtkSMPTools threads; the
 * dot products add fixed blocks in a fixed order, so the iterates do not depend on the thread
 * count.
 */
#ifndef amConjugateGradient_h
#define amConjugateGradient_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <vector>

class amSparseMatrix;

class ANATOMESHFILTERSCORE_EXPORT amConjugateGradient
{
public:
  struct Result
  {
    int Iterations = 0;
    double ResidualNorm = 0.0; // final ||b - A x|| on the free nodes
    double RightHandSideNorm = 0.0;
    bool Converged = false;
  };

  /// Prepare for matrix A (keeps a pointer; A must outlive the solver) and optional fixed nodes.
  void SetMatrix(const amSparseMatrix* A, const std::vector<unsigned char>* fixed = nullptr);

  double RelativeTolerance = 1e-8;
  double AbsoluteTolerance = 1e-14;
  int MaximumIterations = 2000;

  /// Solve A x = b; x holds the initial guess (and the fixed values) on entry.
  Result Solve(const double* b, double* x);

private:
  double Dot(const double* a, const double* b);
  const amSparseMatrix* A = nullptr;
  const std::vector<unsigned char>* Fixed = nullptr;
  std::vector<double> InverseDiagonal, R, Z, P, Q, Rhs, BlockSums;
};

#endif
