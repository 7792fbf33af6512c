// The sliver phase of the element improvement (amTetraImproveSlivers.cxx, amTetraImproveDeviation.cxx)
// on a hand-made mesh: a well-shaped tetrahedron and, under its base, a flat one (a sliver) whose
// apex lies 0.05 mm below that base, both of region 1, every outer face fixed. Within a budget of
// 0.2 mm the sliver is freed (its surface vertices slide: the surface moves 0.15 mm); within 0.01 mm
// nothing frees it, and the surface moves no farther than the budget.
#include "amTetraImproveMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
using amTetraImprove::Sorted;
using amTetraImprove::Tri;

struct CapAndSliver
{
  std::vector<double> P;
  amTetraImprove::Mesh M{ P };
  int Good, Sliver;
  explicit CapAndSliver(double depth)
  {
    // Base a b c in z = 0 (its centroid at the origin), d above it, e just below its centroid.
    const double x[5][3] = { { -1, -0.6, 0 }, { 1, -0.6, 0 }, { 0, 1.2, 0 }, { 0, 0, 1.6 }, { 0, 0, -depth } };
    for (const auto& q : x)
      this->M.AddPoint(q);
    this->Good = this->M.Add({ 0, 1, 2, 3 }, 1);
    this->Sliver = this->M.Add({ 0, 2, 1, 4 }, 1);
    for (const Tri& f :
      { Sorted(0, 1, 3), Sorted(1, 2, 3), Sorted(0, 2, 3), Sorted(0, 1, 4), Sorted(1, 2, 4), Sorted(0, 2, 4) })
      this->M.FixedFaces.insert(f);
    this->M.FixEdgesOfFixedFaces();
  }
};
}

TEST(TetraImproveSlivers, IsSliverAndCountSlivers)
{
  CapAndSliver s(0.05);
  amTetraImprove::Options options;
  EXPECT_FALSE(amTetraImprove::IsSliver(s.M, s.Good, options));
  EXPECT_TRUE(amTetraImprove::IsSliver(s.M, s.Sliver, options));
  EXPECT_EQ(amTetraImprove::CountSlivers(s.M, options), 1);
  s.M.Kill(s.Sliver);
  EXPECT_EQ(amTetraImprove::CountSlivers(s.M, options), 0); // only live elements count
  // A looser bar: nothing in this mesh is flat enough to fail a 0.5 degree one.
  CapAndSliver t(0.05);
  options.SliverDihedral = 0.5;
  options.SliverQuality = 1e9;
  EXPECT_EQ(amTetraImprove::CountSlivers(t.M, options), 0);
}

TEST(TetraImproveSlivers, SurfaceDeviationIsTheFarthestMove)
{
  CapAndSliver s(0.05);
  s.M.Origin = s.M.P;
  const std::vector<Tri> before(s.M.FixedFaces.begin(), s.M.FixedFaces.end());
  EXPECT_NEAR(amTetraImprove::SurfaceDeviation(s.M, before), 0.0, 1e-12);
  s.P[3 * 4 + 2] = -0.15; // the apex e 0.1 farther down
  EXPECT_NEAR(amTetraImprove::SurfaceDeviation(s.M, before), 0.1, 1e-9);
}

TEST(TetraImproveSlivers, FreedWithinABudgetAboveItsDepthKeptBelowIt)
{
  const double depth = 0.05;
  for (const double budget : { 0.2, 0.01 })
  {
    CapAndSliver s(depth);
    amTetraImprove::Options options;
    options.MaximumSurfaceDeviation = budget;
    amTetraImprove::Report report;
    const std::vector<double> original = s.P;
    amTetraImprove::FreeSlivers(
      s.M, options, report, [](int) {}, [&s]() { s.M.FixEdgesOfFixedFaces(); });
    const long left = amTetraImprove::CountSlivers(s.M, options);
    EXPECT_LE(report.SurfaceDeviation, budget + 1e-12) << budget;
    double moved = 0;
    for (size_t i = 0; i < original.size(); i += 3)
      moved = std::max(moved,
        std::sqrt(std::pow(s.P[i] - original[i], 2) + std::pow(s.P[i + 1] - original[i + 1], 2) +
          std::pow(s.P[i + 2] - original[i + 2], 2)));
    if (budget > depth)
    {
      EXPECT_EQ(left, 0);
      EXPECT_GT(report.SurfaceDeviation, 0.0); // the surface moved to free it
      EXPECT_GT(report.Relabels + report.SurfaceMoves + report.SurfaceSplits + report.SurfaceCollapses, 0);
      std::printf("budget %.2f mm: relabels %ld, slides %ld, splits %ld, collapses %ld, surface moved %.4f mm\n",
        budget, report.Relabels, report.SurfaceMoves, report.SurfaceSplits, report.SurfaceCollapses,
        report.SurfaceDeviation);
    }
    else
    {
      EXPECT_EQ(left, 1); // no way to free it within 0.01 mm
      EXPECT_LE(moved, budget + 1e-12);
    }
    long alive = 0;
    for (size_t t = 0; t < s.M.T.size(); ++t)
      alive += s.M.Alive[t] && s.M.R[t] == 1;
    EXPECT_GE(alive, 1); // region 1 keeps an element
  }
}
