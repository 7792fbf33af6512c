#include "amSparseCholesky.h"

#include "amNestedDissection.h"
#include "amSparseMatrix.h"

#include "vtkSMPTools.h"

#include <cholmod.h>
#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace
{
// The supernodal factor calls BLAS; a threaded OpenBLAS splits its sums differently for each
// thread count, which changes the last bits of the result. For results that do not depend on
// the machine's core count, OpenBLAS (when it is the BLAS in use) runs on a fixed number of
// threads while CHOLMOD works (amSparseCholesky::BlasThreads, SolveBlasThreads), and gets its
// setting back afterwards.

// Free nodes from which METIS alone orders the matrix.
constexpr long long LargeMatrix = 20000;

class FixedBlasThreads
{
public:
  explicit FixedBlasThreads(int threads)
  {
    void* blas = dlopen("libopenblas.so.0", RTLD_LAZY | RTLD_NOLOAD);
    if (!blas)
      return;
    this->Set = reinterpret_cast<void (*)(int)>(dlsym(blas, "openblas_set_num_threads"));
    auto get = reinterpret_cast<int (*)()>(dlsym(blas, "openblas_get_num_threads"));
    dlclose(blas); // NOLOAD: only drops the reference taken above
    if (this->Set && get)
    {
      this->Saved = get();
      this->Set(threads);
    }
  }
  ~FixedBlasThreads()
  {
    if (this->Set && this->Saved > 0)
      this->Set(this->Saved);
  }
  FixedBlasThreads(const FixedBlasThreads&) = delete;
  FixedBlasThreads& operator=(const FixedBlasThreads&) = delete;

private:
  void (*Set)(int) = nullptr;
  int Saved = 0;
};
}

/// One solving thread's CHOLMOD state: a Common of its own (CHOLMOD's calls share nothing else
/// but the read-only factor) and its right-hand sides, solutions and workspaces, kept between
/// solves.
struct amSparseCholesky::Worker
{
  cholmod_common Common;
  cholmod_dense* B = nullptr;
  cholmod_dense* X = nullptr;
  cholmod_dense* Y = nullptr;
  cholmod_dense* E = nullptr;

  Worker()
  {
    cholmod_l_start(&this->Common);
    this->Common.print = 0;
    this->Common.error_handler = nullptr;
  }
  ~Worker()
  {
    this->Clear();
    cholmod_l_finish(&this->Common);
  }
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;
  void Clear()
  {
    for (cholmod_dense** d : { &this->B, &this->X, &this->Y, &this->E })
      cholmod_l_free_dense(d, &this->Common);
  }
};

struct amSparseCholesky::Internal
{
  cholmod_common Common;
  cholmod_factor* L = nullptr;
  std::vector<std::unique_ptr<Worker>> Workers;

  Internal()
  {
    cholmod_l_start(&this->Common);
    this->Common.print = 0; // no messages on stdout
    this->Common.error_handler = nullptr;
    this->Common.final_ll = 0; // LDL' stays LDL'
  }
  ~Internal()
  {
    this->Clear();
    cholmod_l_finish(&this->Common);
  }
  void Clear()
  {
    cholmod_l_free_factor(&this->L, &this->Common);
    this->Workers.clear();
  }
};

amSparseCholesky::amSparseCholesky()
  : Impl(new Internal)
{
}

amSparseCholesky::~amSparseCholesky() = default;

bool amSparseCholesky::Factor(const amSparseMatrix* A, const std::vector<unsigned char>* fixed)
{
  const auto start = std::chrono::steady_clock::now();
  Internal& in = *this->Impl;
  in.Clear();
  this->A = A;
  this->Fixed = fixed;
  this->Message.clear();
  const vtkIdType n = A->Size();
  this->FreeIndex.assign(n, -1);
  this->FreeNodes.clear();
  for (vtkIdType i = 0; i < n; ++i)
    if (!fixed || !(*fixed)[i])
    {
      this->FreeIndex[i] = static_cast<vtkIdType>(this->FreeNodes.size());
      this->FreeNodes.push_back(i);
    }
  const vtkIdType m = static_cast<vtkIdType>(this->FreeNodes.size());
  if (m == 0)
  {
    this->Message = "no free node to solve for";
    return false;
  }

  // Lower triangle of the free block in compressed columns: row i of the symmetric CSR matrix
  // is column i, and its entries with column index >= i are that column's lower part.
  vtkIdType nnz = 0;
  for (vtkIdType r = 0; r < m; ++r)
  {
    const vtkIdType i = this->FreeNodes[r];
    for (vtkIdType k = A->RowStart[i]; k < A->RowStart[i + 1]; ++k)
      if (this->FreeIndex[A->Columns[k]] >= r)
        ++nnz;
  }
  cholmod_common* c = &in.Common;
  cholmod_sparse* S = cholmod_l_allocate_sparse(m, m, nnz, 1, 1, -1, CHOLMOD_REAL, c);
  if (!S)
  {
    this->Message = "out of memory for the matrix";
    return false;
  }
  auto* colStart = static_cast<SuiteSparse_long*>(S->p);
  auto* rows = static_cast<SuiteSparse_long*>(S->i);
  auto* values = static_cast<double*>(S->x);
  vtkIdType fill = 0;
  for (vtkIdType r = 0; r < m; ++r)
  {
    colStart[r] = fill;
    const vtkIdType i = this->FreeNodes[r];
    for (vtkIdType k = A->RowStart[i]; k < A->RowStart[i + 1]; ++k)
    {
      // Free indices follow node order, so sorted columns stay sorted.
      const vtkIdType f = this->FreeIndex[A->Columns[k]];
      if (f >= r)
      {
        rows[fill] = f;
        values[fill++] = A->Values[k];
      }
    }
  }
  colStart[m] = fill;

  // CHOLMOD's default orders with AMD and then METIS and keeps the better; on a mesh of tens of
  // thousands of nodes METIS (nested dissection) is the better one, by far, so it alone is used,
  // its two halves ordered at once (amNestedDissection), and CHOLMOD is given the order.
  std::vector<SuiteSparse_long> given;
  // METIS numbers the graph's edges with 32-bit integers: a larger graph takes CHOLMOD's default.
  if (m >= LargeMatrix && A->NumberOfNonZeros() < std::numeric_limits<int>::max())
  {
    std::string why;
    std::vector<long long> order;
    if (!this->NestedDissection(order, why))
    {
      this->Message = why;
      cholmod_l_free_sparse(&S, c);
      return false;
    }
    given.assign(order.begin(), order.end());
    c->nmethods = 1;
    c->method[0].ordering = CHOLMOD_GIVEN;
  }
  else
    c->nmethods = 0;
  FixedBlasThreads blas(this->BlasThreads);
  in.L = given.empty() ? cholmod_l_analyze(S, c) : cholmod_l_analyze_p(S, given.data(), nullptr, 0, c);
  bool ok = in.L && c->status >= CHOLMOD_OK;
  if (ok)
    ok = cholmod_l_factorize(S, in.L, c) && c->status == CHOLMOD_OK;
  if (!ok)
  {
    if (c->status == CHOLMOD_NOT_POSDEF)
      this->Message = "the matrix is not positive definite (column " +
        std::to_string(in.L ? static_cast<long long>(this->FreeNodes[in.L->minor]) : -1) +
        "): a node without a path to a fixed node, or a non-positive conductivity";
    else if (c->status == CHOLMOD_OUT_OF_MEMORY || c->status == CHOLMOD_TOO_LARGE)
      this->Message = "out of memory for the Cholesky factor";
    else
      this->Message = "CHOLMOD failed (status " + std::to_string(c->status) + ")";
    cholmod_l_free_sparse(&S, c);
    in.Clear();
    return false;
  }
  cholmod_l_free_sparse(&S, c);
  // A singular matrix (e.g. a part with no fixed node: potential defined up to a constant) can
  // factor "successfully" with a pivot at rounding level; the pivot ratio shows it.
  const double rcond = cholmod_l_rcond(in.L, c);
  if (!(rcond > 1e-13))
  {
    this->Message = "the matrix is not positive definite (numerically singular, pivot ratio " + std::to_string(rcond) +
      "): a part without a fixed node, or a zero conductivity";
    in.Clear();
    return false;
  }
  this->NonZeros = c->lnz;
  this->Flops = c->fl;
  this->Supernodal = in.L->is_super != 0;
  static const char* names[] = { "natural", "given", "AMD", "METIS", "NESDIS", "COLAMD", "postordered" };
  const int ordering = in.L->ordering;
  this->OrderingName = !given.empty() ? "METIS" : (ordering >= 0 && ordering <= 6 ? names[ordering] : "unknown");
  this->Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

bool amSparseCholesky::NestedDissection(std::vector<long long>& order, std::string& why) const
{
  // The free block's graph: both directions of every coupling, without the diagonal.
  const amSparseMatrix& A = *this->A;
  const vtkIdType m = static_cast<vtkIdType>(this->FreeNodes.size());
  std::vector<int> start(1, 0), adjacent;
  adjacent.reserve(static_cast<size_t>(A.NumberOfNonZeros()));
  for (vtkIdType r = 0; r < m; ++r)
  {
    const vtkIdType i = this->FreeNodes[r];
    for (vtkIdType k = A.RowStart[i]; k < A.RowStart[i + 1]; ++k)
    {
      const vtkIdType f = this->FreeIndex[A.Columns[k]];
      if (f >= 0 && f != r)
        adjacent.push_back(static_cast<int>(f));
    }
    start.push_back(static_cast<int>(adjacent.size()));
  }
  return amNestedDissection::Order(start, adjacent, order, why);
}

bool amSparseCholesky::Solve(const double* b, double* x, int count)
{
  Internal& in = *this->Impl;
  if (count < 1)
    return true;
  // The columns in fixed shares, one per worker, at least two columns each (one column would take
  // BLAS's vector products instead of its matrix products). The shares depend on SolveThreads and
  // count only, never on the cores that run them: the same bytes on any machine. (A share's width
  // changes how BLAS blocks the columns, so another SolveThreads may round the last bits apart.)
  const int shares = std::max(1, std::min(this->SolveThreads, count / 2));
  while (static_cast<int>(in.Workers.size()) < shares)
    in.Workers.push_back(std::unique_ptr<Worker>(new Worker));
  std::vector<char> ok(static_cast<size_t>(shares), 0);
  FixedBlasThreads blas(this->SolveBlasThreads);
  vtkSMPTools::For(0, shares, 1, [&](vtkIdType s0, vtkIdType s1) {
    for (vtkIdType s = s0; s < s1; ++s)
    {
      const int first = static_cast<int>(s * count / shares), last = static_cast<int>((s + 1) * count / shares);
      ok[s] = this->SolveColumns(*in.Workers[s], b, x, first, last - first);
    }
  });
  return std::all_of(ok.begin(), ok.end(), [](char k) { return k != 0; });
}

bool amSparseCholesky::SolveColumns(Worker& w, const double* b, double* x, int first, int count)
{
  const amSparseMatrix& A = *this->A;
  const vtkIdType n = A.Size();
  const vtkIdType m = static_cast<vtkIdType>(this->FreeNodes.size());
  if (!w.B || static_cast<int>(w.B->ncol) != count)
  {
    cholmod_l_free_dense(&w.B, &w.Common);
    w.B = cholmod_l_zeros(m, count, CHOLMOD_REAL, &w.Common);
    if (!w.B)
      return false;
  }
  auto* rhs = static_cast<double*>(w.B->x);
  for (int col = 0; col < count; ++col)
  {
    const double* bc = b ? b + (first + col) * n : nullptr;
    const double* xc = x + (first + col) * n;
    double* rc = rhs + col * m;
    for (vtkIdType r = 0; r < m; ++r)
    {
      const vtkIdType i = this->FreeNodes[r];
      double s = bc ? bc[i] : 0.0;
      for (vtkIdType k = A.RowStart[i]; k < A.RowStart[i + 1]; ++k)
        if (this->FreeIndex[A.Columns[k]] < 0)
          s -= A.Values[k] * xc[A.Columns[k]];
      rc[r] = s;
    }
  }
  if (!cholmod_l_solve2(CHOLMOD_A, this->Impl->L, w.B, nullptr, &w.X, nullptr, &w.Y, &w.E, &w.Common))
    return false;
  const auto* solution = static_cast<const double*>(w.X->x);
  for (int col = 0; col < count; ++col)
    for (vtkIdType r = 0; r < m; ++r)
      x[(first + col) * n + this->FreeNodes[r]] = solution[col * m + r];
  return true;
}
