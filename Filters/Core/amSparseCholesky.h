/**
 * @class   amSparseCholesky
 * @brief   Sparse Cholesky factorisation (CHOLMOD) of a symmetric positive definite P1 matrix
 *          restricted to its free nodes, for solving the same system with many right-hand sides.
 *
 * Same conventions as amConjugateGradient: the matrix is an amSparseMatrix (both triangles
 * stored), nodes flagged in 'fixed' are Dirichlet nodes whose value is taken from x on entry and
 * moved to the right-hand side, and Solve(b, x) overwrites the free entries of x. The
 * factorisation (fill-reducing ordering chosen by CHOLMOD: AMD or nested dissection, supernodal
 * when the factor is dense enough) is done once by Factor(); each Solve() is then two triangular
 * sweeps, which is what makes a quasi-static torso solve at every time step cheap. Workspace is
 * kept between solves, so the time loop allocates nothing.
 */
#ifndef amSparseCholesky_h
#define amSparseCholesky_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <memory>
#include <string>
#include <vector>

class amSparseMatrix;

class ANATOMESHFILTERSCORE_EXPORT amSparseCholesky
{
public:
  amSparseCholesky();
  ~amSparseCholesky();
  amSparseCholesky(const amSparseCholesky&) = delete;
  amSparseCholesky& operator=(const amSparseCholesky&) = delete;

  /// Factor the free-node block of A (keeps a pointer to A and fixed: they must outlive the
  /// solver). False with Error() set when the block is not positive definite, has no free node,
  /// or CHOLMOD runs out of memory.
  bool Factor(const amSparseMatrix* A, const std::vector<unsigned char>* fixed = nullptr);

  /// Solve A x = b on the free nodes; the fixed entries of x hold the Dirichlet values on entry
  /// and are not changed. Call only after a successful Factor(). With count > 1, b and x hold
  /// count vectors one after another (column-major): one pass over the factor serves them all,
  /// which is several times faster per vector than solving them one by one. b may be null
  /// (zero right-hand side). False only when the workspace cannot be allocated.
  bool Solve(const double* b, double* x, int count = 1);

  const std::string& Error() const { return this->Message; }

  /// OpenBLAS's threads while CHOLMOD factors (a fixed number: the results do not depend on the
  /// machine's cores). Two suit a large factor, whose dense products are most of its time; one
  /// suits a small system, where waking a second thread costs more than it gives.
  int BlasThreads = 2;
  /// OpenBLAS's threads while CHOLMOD solves. One: the sweeps read the factor once and do little
  /// arithmetic on what they read, and between solves a second thread would spin on the other
  /// core (OpenBLAS's workers wait busily for a while after each call), taking it from the work
  /// done between the solves (the next right-hand sides, the files being written).
  int SolveBlasThreads = 1;
  /// Threads that share a Solve() of several right-hand sides, each sweeping the factor for its
  /// own columns (at least two). The split depends on this number only, so the results are the
  /// same bytes on any machine; another number may round their last bits differently.
  int SolveThreads = 2;

  /// Figures of the factorisation: non-zeros of L, floating-point operations, seconds, and
  /// whether the supernodal (BLAS) form was used; the ordering ("AMD", "METIS", "NESDIS", ...).
  double FactorNonZeros() const { return this->NonZeros; }
  double FactorFlops() const { return this->Flops; }
  double FactorSeconds() const { return this->Seconds; }
  bool IsSupernodal() const { return this->Supernodal; }
  const std::string& Ordering() const { return this->OrderingName; }

private:
  struct Internal;
  struct Worker;
  bool NestedDissection(std::vector<long long>& order, std::string& why) const;
  bool SolveColumns(Worker& worker, const double* b, double* x, int first, int count);
  std::unique_ptr<Internal> Impl;
  const amSparseMatrix* A = nullptr;
  const std::vector<unsigned char>* Fixed = nullptr;
  std::vector<vtkIdType> FreeIndex; // node -> free row (-1 fixed)
  std::vector<vtkIdType> FreeNodes; // free row -> node
  std::string Message;
  double NonZeros = 0, Flops = 0, Seconds = 0;
  bool Supernodal = false;
  std::string OrderingName;
};

#endif
