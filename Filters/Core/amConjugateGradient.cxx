#include "amConjugateGradient.h"

#include "amSparseMatrix.h"

#include "amThreading.h"
#include "vtkSMPTools.h"

#include <cmath>

namespace
{
constexpr vtkIdType Block = 4096; // dot products: fixed blocks, added in order
}

void amConjugateGradient::SetMatrix(const amSparseMatrix* A, const std::vector<unsigned char>* fixed)
{
  this->A = A;
  this->Fixed = fixed;
  const vtkIdType n = A->Size();
  this->InverseDiagonal = A->Diagonal();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool free = !fixed || !(*fixed)[i];
    const double d = this->InverseDiagonal[i];
    this->InverseDiagonal[i] = (free && d > 0) ? 1.0 / d : 0.0;
  }
  for (auto* v : { &this->R, &this->Z, &this->P, &this->Q, &this->Rhs })
    v->assign(n, 0.0);
  this->BlockSums.assign((n + Block - 1) / Block, 0.0);
}

double amConjugateGradient::Dot(const double* a, const double* b)
{
  const vtkIdType n = this->A->Size();
  double* sums = this->BlockSums.data();
  auto sum = [=](vtkIdType begin, vtkIdType end) {
    for (vtkIdType blk = begin; blk < end; ++blk)
    {
      double s = 0.0;
      const vtkIdType last = std::min(n, (blk + 1) * Block);
      for (vtkIdType i = blk * Block; i < last; ++i)
        s += a[i] * b[i];
      sums[blk] = s;
    }
  };
  const vtkIdType blocks = static_cast<vtkIdType>(this->BlockSums.size());
  if (blocks < 12)
    sum(0, blocks); // too short to share out
  else
    vtkSMPTools::For(0, blocks, 2, sum);
  double total = 0.0;
  for (double s : this->BlockSums)
    total += s;
  return total;
}

amConjugateGradient::Result amConjugateGradient::Solve(const double* b, double* x)
{
  Result result;
  const vtkIdType n = this->A->Size();
  const unsigned char* fixed = this->Fixed ? this->Fixed->data() : nullptr;
  double* r = this->R.data();
  double* z = this->Z.data();
  double* p = this->P.data();
  double* q = this->Q.data();
  double* rhs = this->Rhs.data();
  const double* invD = this->InverseDiagonal.data();

  // The norm to reach is relative to the right-hand side of the free nodes' system, b minus the
  // coupling to the fixed values (with Dirichlet data and b = 0 that is the whole forcing).
  if (fixed)
  {
    amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
        z[i] = fixed[i] ? x[i] : 0.0;
    });
    this->A->Multiply(z, q);
  }
  amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
      rhs[i] = (fixed && fixed[i]) ? 0.0 : b[i] - (fixed ? q[i] : 0.0);
  });
  result.RightHandSideNorm = std::sqrt(this->Dot(rhs, rhs));
  this->A->Multiply(x, q);
  amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      r[i] = (fixed && fixed[i]) ? 0.0 : b[i] - q[i];
      z[i] = invD[i] * r[i];
      p[i] = z[i];
    }
  });
  double rr = this->Dot(r, r);
  const double target = std::max(this->RelativeTolerance * result.RightHandSideNorm, this->AbsoluteTolerance);
  double rz = this->Dot(r, z);
  while (std::sqrt(rr) > target && result.Iterations < this->MaximumIterations)
  {
    this->A->Multiply(p, q);
    if (fixed)
      amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
          if (fixed[i])
            q[i] = 0.0;
      });
    const double pq = this->Dot(p, q);
    if (!(pq > 0))
      break; // not positive definite on the free nodes (or p = 0)
    const double alpha = rz / pq;
    amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        x[i] += alpha * p[i];
        r[i] -= alpha * q[i];
        z[i] = invD[i] * r[i];
      }
    });
    const double rzNew = this->Dot(r, z);
    rr = this->Dot(r, r);
    const double beta = rzNew / rz;
    rz = rzNew;
    amThreading::For(0, n, [=](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
        p[i] = z[i] + beta * p[i];
    });
    ++result.Iterations;
  }
  result.ResidualNorm = std::sqrt(rr);
  result.Converged = result.ResidualNorm <= target;
  return result;
}
