// The edge split of the element improvement (amTetraImproveInsert.cxx: SplitEdge and KeepInsertion)
// on a hand-made configuration: six needles around a long edge (u below, v above, a hexagon of
// radius 1 around its middle). Split at its midpoint, the needles become twelve elements of half
// their height; the split is undone when they cannot reach the goal, and refused on a fixed edge.
#include "amTetraGeometry.h"
#include "amTetraImproveMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
using amTetraImprove::Tet;

struct Needles
{
  std::vector<double> P;
  amTetraImprove::Mesh M{ P };
  int U, V;
  Needles()
  {
    this->P.reserve(3 * 9); // u, v, the hexagon and the split's new vertex
    const double u[3] = { 0, 0, -2 }, v[3] = { 0, 0, 2 };
    this->U = this->M.AddPoint(u);
    this->V = this->M.AddPoint(v);
    std::vector<int> ring;
    for (int i = 0; i < 6; ++i)
    {
      const double a = i * 3.14159265358979323846 / 3.0, x[3] = { std::cos(a), std::sin(a), 0 };
      ring.push_back(this->M.AddPoint(x));
    }
    for (int i = 0; i < 6; ++i) // counter-clockwise seen from v: positively oriented
      this->M.Add({ this->U, this->V, ring[i], ring[(i + 1) % 6] }, 1);
  }
  // The live elements: their number, the worst objective, the total signed volume.
  void Live(int& count, double& worst, double& volume) const
  {
    count = 0;
    worst = 1e30;
    volume = 0;
    for (size_t t = 0; t < this->M.T.size(); ++t)
      if (this->M.Alive[t])
      {
        const Tet& x = this->M.T[t];
        ++count;
        worst = std::min(worst, this->M.Objectives[t]);
        volume += amTetraGeometry::SignedVolume(this->M.X(x[0]), this->M.X(x[1]), this->M.X(x[2]), this->M.X(x[3]));
      }
  }
};
}

TEST(TetraImproveInsert, SplitEdgeTurnsNeedlesIntoBetterElements)
{
  Needles s;
  int before, after;
  double worstBefore, worstAfter, volumeBefore, volumeAfter;
  s.Live(before, worstBefore, volumeBefore);
  ASSERT_EQ(before, 6);
  std::vector<int> tets, ring;
  ASSERT_TRUE(amTetraImprove::SplitEdge(s.M, s.U, s.V, 0.0, tets, ring));
  s.Live(after, worstAfter, volumeAfter);
  EXPECT_EQ(after, 12);
  EXPECT_GT(worstAfter, worstBefore);
  EXPECT_NEAR(volumeAfter, volumeBefore, 1e-12); // the new vertex moved inside its star only
  const int w = static_cast<int>(s.M.Inc.size()) - 1;
  EXPECT_EQ(s.M.Inc[w].size(), 12u);
  EXPECT_LT(std::fabs(s.M.X(w)[0]) + std::fabs(s.M.X(w)[1]), 1e-9); // on the axis, by symmetry
}

TEST(TetraImproveInsert, SplitUndoneBelowItsGoalAndRefusedOnAFixedEdge)
{
  {
    Needles s;
    int before, after;
    double worstBefore, worstAfter, volumeBefore, volumeAfter;
    s.Live(before, worstBefore, volumeBefore);
    std::vector<int> tets, ring;
    EXPECT_FALSE(amTetraImprove::SplitEdge(s.M, s.U, s.V, 2.0, tets, ring)); // no element reaches 2 (> 1)
    s.Live(after, worstAfter, volumeAfter);
    EXPECT_EQ(after, before);
    EXPECT_DOUBLE_EQ(worstAfter, worstBefore);
    EXPECT_NEAR(volumeAfter, volumeBefore, 1e-12);
    EXPECT_TRUE(s.M.Inc.back().empty()); // the new vertex is left unused
  }
  {
    Needles s;
    s.M.FixedEdges.insert(amTetraImprove::EdgeKey(s.U, s.V));
    std::vector<int> tets, ring;
    EXPECT_FALSE(amTetraImprove::SplitEdge(s.M, s.U, s.V, 0.0, tets, ring));
    EXPECT_EQ(s.M.Inc.size(), 8u); // nothing added
  }
}
