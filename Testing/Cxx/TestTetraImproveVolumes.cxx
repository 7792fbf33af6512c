// The tetrahedral mesh's volume correction (amTetraImproveVolumes.cxx, through
// amTetraMeshOptimizer::Optimize): regions get their target volumes, no element inverts, and two
// parts of the boundary brought into each other are moved back.
#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amTetraGeometry.h"
#include "amTetraImproveMesh.h"
#include "amTetraLattice.h"
#include "amTetraMeshOptimizer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

namespace
{
struct TwoBlocks
{
  std::vector<double> Points;
  std::vector<std::array<int, 4>> Tets;
  std::vector<int> Regions;
};

/// Two blocks of 3 x 3 x 3 mm (lattices of unit cubes, six tetrahedra each): region 1 at x in
/// [0, 3], region 2 at x in [3 + gap, 6 + gap].
TwoBlocks Blocks(double gap)
{
  TwoBlocks b;
  for (int block = 0; block < 2; ++block)
  {
    std::vector<double> p;
    amTetraImprove::Mesh m(p);
    amTest::Lattice(4, 0.0, p, m);
    const int base = static_cast<int>(b.Points.size() / 3);
    for (size_t v = 0; v < p.size() / 3; ++v)
    {
      b.Points.push_back(p[3 * v] + block * (3 + gap));
      b.Points.push_back(p[3 * v + 1]);
      b.Points.push_back(p[3 * v + 2]);
    }
    for (const auto& t : m.T)
    {
      b.Tets.push_back({ { t[0] + base, t[1] + base, t[2] + base, t[3] + base } });
      b.Regions.push_back(block + 1);
    }
  }
  return b;
}

std::map<int, double> Volumes(const TwoBlocks& b, int& inverted)
{
  std::map<int, double> v;
  inverted = 0;
  for (size_t t = 0; t < b.Tets.size(); ++t)
  {
    const auto& x = b.Tets[t];
    const double* p = b.Points.data();
    const double vol = amTetraGeometry::SignedVolume(p + 3 * x[0], p + 3 * x[1], p + 3 * x[2], p + 3 * x[3]);
    inverted += vol <= 0;
    v[b.Regions[t]] += vol;
  }
  return v;
}

/// The boundary's triangles (faces of one tetrahedron) that cross another boundary triangle.
size_t BoundaryCrossings(const TwoBlocks& b)
{
  std::map<amTetraImprove::Tri, int> count;
  for (const auto& t : b.Tets)
    for (int i = 0; i < 4; ++i)
      ++count[amTetraImprove::Sorted(t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4])];
  amSurfaceMesh surface;
  for (const auto& kv : count)
    if (kv.second == 1)
      surface.Triangles.push_back({ { kv.first[0], kv.first[1], kv.first[2] } });
  std::vector<std::array<double, 3>> points(b.Points.size() / 3);
  for (size_t v = 0; v < points.size(); ++v)
    points[v] = { { b.Points[3 * v], b.Points[3 * v + 1], b.Points[3 * v + 2] } };
  return amSelfIntersection::AllTriangles(surface, points).size();
}

amTetraMeshOptimizer::Report Correct(TwoBlocks& b, double target, double limit)
{
  amTetraMeshOptimizer::Options options;
  options.Passes = 0;
  options.TargetVolumes = { { 1, target }, { 2, target } };
  options.MaximumVolumeOffset = limit;
  return amTetraMeshOptimizer::Optimize(b.Points, b.Tets, b.Regions, {}, options);
}
}

// Far apart, each block gets its target: 27 -> 30 mm^3 (the faces move out by about a tenth of a
// millimetre), every element positive.
TEST(TetraImproveVolumes, EachRegionGetsItsTarget)
{
  TwoBlocks b = Blocks(10.0);
  const amTetraMeshOptimizer::Report report = Correct(b, 30.0, 1.0);
  int inverted = 0;
  const auto v = Volumes(b, inverted);
  EXPECT_EQ(inverted, 0);
  EXPECT_NEAR(v.at(1), 30.0, 0.3);
  EXPECT_NEAR(v.at(2), 30.0, 0.3);
  EXPECT_GT(report.VolumeMoves, 0);
  EXPECT_GT(report.VolumeDisplacement, 0.05);
  EXPECT_LE(report.VolumeDisplacement, 1.0 + 1e-12);
}

// A gap of 0.1 mm between the blocks, and targets that push their facing sides 0.4 mm out: the
// moves that would run the blocks into each other are taken back; the others stay.
TEST(TetraImproveVolumes, BlocksDoNotRunIntoEachOther)
{
  TwoBlocks apart = Blocks(10.0);
  Correct(apart, 45.0, 1.0);
  double reach = 0; // how far region 1 reaches beyond x = 3 when nothing is in the way
  for (size_t v = 0; v < apart.Points.size() / 3; ++v)
    if (apart.Points[3 * v] < 8)
      reach = std::max(reach, apart.Points[3 * v] - 3);
  ASSERT_GT(reach, 0.1) << "the moves must be long enough to cross the gap for the test to mean anything";

  TwoBlocks b = Blocks(0.1);
  ASSERT_EQ(BoundaryCrossings(b), 0u);
  const amTetraMeshOptimizer::Report report = Correct(b, 45.0, 1.0);
  int inverted = 0;
  const auto v = Volumes(b, inverted);
  EXPECT_EQ(inverted, 0);
  EXPECT_EQ(BoundaryCrossings(b), 0u);
  EXPECT_GT(report.VolumeMoves, 0);
  EXPECT_GT(v.at(1), 27.5); // the other sides grew
  EXPECT_GT(v.at(2), 27.5);
}
