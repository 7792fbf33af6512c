// amSparseCholesky: several right-hand sides at once, shared between solving threads.
#include "amLatticeMatrix.h"
#include "amSparseCholesky.h"

#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

TEST(SparseCholesky, SharedSolvesAreTheSameBytesOnAnyCores)
{
  const amTest::LatticeMatrix lattice(30);
  const vtkIdType n = lattice.A.Size();
  amSparseCholesky solver;
  ASSERT_TRUE(solver.Factor(&lattice.A, &lattice.Fixed)) << solver.Error();
  // Large enough for the supernodal factor (the solves then call BLAS on each thread) and for the
  // nested dissection: less than half the fill of the lattice's own banded order (its n rows hold
  // about 900 entries each).
  EXPECT_TRUE(solver.IsSupernodal());
  EXPECT_EQ(solver.Ordering(), "METIS");
  EXPECT_LT(solver.FactorNonZeros(), 0.4 * n * 900);

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
