// amSparseCholesky: several right-hand sides at once, shared between solving threads.
#include "amSparseCholesky.h"
#include "amSparseMatrix.h"

#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace
{
/// A lattice of n^3 nodes, each cube cut into six tetrahedra; the graph Laplacian plus a little of
/// the identity (symmetric positive definite), the nodes of the face x = 0 fixed.
struct Lattice
{
  amSparseMatrix A;
  std::vector<unsigned char> Fixed;

  explicit Lattice(int n)
  {
    auto id = [n](int i, int j, int k) { return static_cast<vtkIdType>((k * n + j) * n + i); };
    std::vector<std::array<vtkIdType, 4>> tets;
    for (int k = 0; k + 1 < n; ++k)
      for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
        {
          const vtkIdType c[8] = { id(i, j, k), id(i + 1, j, k), id(i, j + 1, k), id(i + 1, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i, j + 1, k + 1), id(i + 1, j + 1, k + 1) };
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
    this->Fixed.assign(static_cast<size_t>(size), 0);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        this->Fixed[id(0, j, k)] = 1;
  }
};
}

TEST(SparseCholesky, SharedSolvesAreTheSameBytesOnAnyCores)
{
  const Lattice lattice(30);
  const vtkIdType n = lattice.A.Size();
  amSparseCholesky solver;
  ASSERT_TRUE(solver.Factor(&lattice.A, &lattice.Fixed)) << solver.Error();
  // Large enough for the supernodal factor: the solves then call BLAS on each thread.
  EXPECT_TRUE(solver.IsSupernodal());

  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int count : { 1, 2, 3, 5, 9, 17 })
  {
    std::vector<double> b(static_cast<size_t>(n * count)), start(b.size());
    for (size_t i = 0; i < b.size(); ++i)
    {
      b[i] = uniform(random);
      start[i] = lattice.Fixed[i % n] ? uniform(random) : 0.0; // the Dirichlet values
    }
    // One share; two shares run on one thread, then on two.
    std::vector<std::vector<double>> x;
    for (int run = 0; run < 3; ++run)
    {
      solver.SolveThreads = run == 0 ? 1 : 2;
      vtkSMPTools::Initialize(run == 1 ? 1 : 2);
      x.push_back(start);
      ASSERT_TRUE(solver.Solve(b.data(), x.back().data(), count));
    }
    vtkSMPTools::Initialize(2);
    EXPECT_EQ(std::memcmp(x[1].data(), x[2].data(), x[1].size() * sizeof(double)), 0)
      << count << " columns: two shares on two threads differ from the same on one";
    double largest = 0, apart = 0;
    for (size_t i = 0; i < x[0].size(); ++i)
    {
      largest = std::max(largest, std::fabs(x[0][i]));
      apart = std::max(apart, std::fabs(x[0][i] - x[1][i]));
    }
    EXPECT_LE(apart, 1e-12 * largest) << count << " columns: one share and two differ by more than rounding";

    // Each column solves its own system: A x = b on the free rows, the fixed values unchanged.
    double worst = 0;
    std::vector<double> ax(static_cast<size_t>(n));
    for (int c = 0; c < count; ++c)
    {
      const double* xc = x[1].data() + c * n;
      lattice.A.Multiply(xc, ax.data());
      for (vtkIdType r = 0; r < n; ++r)
        if (lattice.Fixed[r])
          EXPECT_EQ(xc[r], start[c * n + r]);
        else
          worst = std::max(worst, std::fabs(ax[r] - b[c * n + r]));
    }
    EXPECT_LT(worst, 1e-9) << count << " columns";
  }
}
