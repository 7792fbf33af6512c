// The optimizer's local operations (Filters/Volume/Improvement) on meshes small enough to follow
// by hand.
#include "amTetraGeometry.h"
#include "amTetraImproveMesh.h"
#include "amTetraLattice.h"
#include "amTetraMeshOptimizer.h"

#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

namespace
{
using amTetraImprove::Tet;

/// Two tetrahedra on face abc: a cap (d 0.12 above the centroid of abc, its three small
/// dihedral angles at the edges of that face) and e under it. Every vertex is fixed.
struct Cap
{
  std::vector<double> Points = { 0, 0, 0, /*b*/ 2, 0, 0, /*c*/ 1, 1.7, 0, /*d*/ 1, 0.57, 0.12, /*e*/ 1.6, 1.2, -1.2 };
  amTetraImprove::Mesh M{ Points };
  Cap()
  {
    this->M.Inc.resize(5);
    this->M.FixedVertex.assign(5, 1);
    this->M.Dirty.assign(5, 0);
    this->M.Add(this->Positive({ 0, 1, 2, 3 }), 7);
    this->M.Add(this->Positive({ 0, 1, 2, 4 }), 7);
  }
  Tet Positive(Tet t) const
  {
    const double* p = this->Points.data();
    if (amTetraGeometry::SignedVolume(p + 3 * t[0], p + 3 * t[1], p + 3 * t[2], p + 3 * t[3]) < 0)
      std::swap(t[2], t[3]);
    return t;
  }
  /// The live tetrahedra's worst objective and total volume.
  std::pair<double, double> WorstAndVolume() const
  {
    double worst = 1, volume = 0;
    for (size_t t = 0; t < this->M.T.size(); ++t)
      if (this->M.Alive[t])
      {
        const Tet& x = this->M.T[t];
        const double v =
          amTetraGeometry::SignedVolume(this->M.X(x[0]), this->M.X(x[1]), this->M.X(x[2]), this->M.X(x[3]));
        EXPECT_GT(v, 0);
        volume += v;
        worst = std::min(worst, this->M.Objectives[t]);
      }
    return { worst, volume };
  }
  long Alive() const { return std::count(this->M.Alive.begin(), this->M.Alive.end(), 1); }
};
}

// Every edge of the cap is fixed, so no edge split reaches it; its one free face, split in a 2-6,
// gives a vertex that moves off the face into the element below, and each of the six elements
// is better than the cap was.
TEST(TetraImprove, SplitFaceMendsACapWithoutAFreeEdge)
{
  Cap cap;
  const auto [worstBefore, volumeBefore] = cap.WorstAndVolume();
  EXPECT_LT(worstBefore, 0.2); // Q about 6.9
  ASSERT_TRUE(amTetraImprove::SplitFace(cap.M, amTetraImprove::Sorted(0, 1, 2), 0.2));
  EXPECT_EQ(cap.Alive(), 6);
  EXPECT_EQ(cap.M.Inc.size(), 6u);
  EXPECT_EQ(cap.M.Inc[5].size(), 6u);    // the new vertex is in all six
  EXPECT_LT(cap.Points[3 * 5 + 2], 0.0); // below the face, towards e
  const auto [worstAfter, volumeAfter] = cap.WorstAndVolume();
  EXPECT_GE(worstAfter, 0.2);
  EXPECT_NEAR(volumeAfter, volumeBefore, 1e-12);
  for (size_t t = 0; t < cap.M.T.size(); ++t)
    if (cap.M.Alive[t])
      EXPECT_EQ(cap.M.R[t], 7);
}

// A goal the split cannot reach leaves the two elements as they were; a fixed face is never split.
TEST(TetraImprove, SplitFaceUndoneBelowItsGoalAndNeverOnAFixedFace)
{
  Cap cap;
  const auto [worstBefore, volumeBefore] = cap.WorstAndVolume();
  EXPECT_FALSE(amTetraImprove::SplitFace(cap.M, amTetraImprove::Sorted(0, 1, 2), 0.9));
  EXPECT_EQ(cap.Alive(), 2);
  EXPECT_TRUE(cap.M.Inc[5].empty());
  const auto [worstAfter, volumeAfter] = cap.WorstAndVolume();
  EXPECT_DOUBLE_EQ(worstAfter, worstBefore);
  EXPECT_DOUBLE_EQ(volumeAfter, volumeBefore);

  cap.M.FixedFaces.insert(amTetraImprove::Sorted(0, 1, 2));
  EXPECT_FALSE(amTetraImprove::SplitFace(cap.M, amTetraImprove::Sorted(0, 1, 2), 0.2));
  EXPECT_EQ(cap.Alive(), 2);
  // A face on one element only (the mesh's boundary) has nothing to split into.
  EXPECT_FALSE(amTetraImprove::SplitFace(cap.M, amTetraImprove::Sorted(0, 1, 3), 0.2));
}

// SmoothAll smooths each colour class of SmoothingColours on the threads at once: the mesh it
// leaves is, bit for bit, the serial loop's over the classes in turn, on two threads and on one.
// No two vertices of a class share an element; every free vertex of a fully dirty mesh is in one.
TEST(TetraImprove, SmoothAllIsTheSerialLoopOverItsColoursBitForBit)
{
  std::vector<double> serialPoints, twoPoints, onePoints;
  amTetraImprove::Mesh serial(serialPoints), two(twoPoints), one(onePoints);
  amTest::Lattice(22, 0.3, serialPoints, serial);
  amTest::Lattice(22, 0.3, twoPoints, two);
  amTest::Lattice(22, 0.3, onePoints, one);
  ASSERT_GT(serial.Inc.size(), 2 * 4096u);
  vtkSMPTools::SetBackend("STDThread");
  for (int pass = 0; pass < 2; ++pass)
  {
    const auto colours = amTetraImprove::SmoothingColours(serial, serial.Inc.size());
    EXPECT_GT(colours.size(), 3u);
    EXPECT_LT(colours.size(), 40u);
    std::vector<int> colourOf(serial.Inc.size(), -1);
    for (size_t c = 0; c < colours.size(); ++c)
      for (int v : colours[c])
      {
        EXPECT_EQ(colourOf[v], -1) << "vertex " << v << " in two classes";
        colourOf[v] = static_cast<int>(c);
      }
    for (size_t t = 0; t < serial.T.size(); ++t)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
        {
          const int a = serial.T[t][i], b = serial.T[t][j];
          if (colourOf[a] >= 0)
            EXPECT_NE(colourOf[a], colourOf[b]) << "neighbours " << a << " and " << b;
        }
    if (pass == 0)
      for (size_t v = 0; v < serial.Inc.size(); ++v)
        EXPECT_EQ(colourOf[v] >= 0, !serial.FixedVertex[v]) << "vertex " << v;
    long serialMoves = 0;
    for (const auto& vertices : colours)
      for (int v : vertices)
      {
        if (!serial.Dirty[v])
          continue;
        serial.Dirty[v] = 0;
        serialMoves += amTetraImprove::Smooth(serial, v);
      }
    vtkSMPTools::Initialize(2);
    const long twoMoves = amTetraImprove::SmoothAll(two, two.Inc.size());
    vtkSMPTools::Initialize(1);
    const long oneMoves = amTetraImprove::SmoothAll(one, one.Inc.size());
    EXPECT_GT(serialMoves, 1000);
    EXPECT_EQ(twoMoves, serialMoves);
    EXPECT_EQ(oneMoves, serialMoves);
    EXPECT_TRUE(serialPoints == twoPoints) << "pass " << pass;
    EXPECT_TRUE(serialPoints == onePoints) << "pass " << pass;
    EXPECT_TRUE(serial.Objectives == two.Objectives && serial.Objectives == one.Objectives);
    EXPECT_TRUE(serial.Dirty == two.Dirty && serial.Dirty == one.Dirty);
    EXPECT_TRUE(serial.Tried == two.Tried && serial.Tried == one.Tried);
  }
  vtkSMPTools::Initialize(2);
}

// TopologyPass plans its blocks' flips on two threads at once and makes them in order: the same
// tetrahedra, in the same order, as the serial loop of Mend (a lattice jittered so far that
// thousands of elements are bad; many blocks, with changes that touch each other within one).
TEST(TetraImprove, TopologyPassIsTheSerialLoopBitForBit)
{
  std::vector<double> serialPoints, blockPoints;
  amTetraImprove::Mesh serial(serialPoints), blocks(blockPoints);
  amTest::Lattice(16, 0.45, serialPoints, serial);
  amTest::Lattice(16, 0.45, blockPoints, blocks);
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  const double bad = 1 / 1.6, split = 1 / 5.0;
  for (int pass = 0; pass < 2; ++pass)
  {
    amTetraMeshOptimizer::Report serialReport, blockReport;
    std::vector<int> ringTets, ring;
    long serialChanges = 0;
    const size_t limit = serial.T.size();
    for (size_t t = 0; t < limit; ++t)
      if (serial.Alive[t] && !serial.Tried[t] && serial.Objectives[t] < bad)
        serialChanges += amTetraImprove::Mend(serial, static_cast<int>(t), split, 7, serialReport, ringTets, ring);
    const long blockChanges = amTetraImprove::TopologyPass(blocks, bad, split, 7, blockReport);
    if (pass == 0)
    {
      EXPECT_GT(serial.T.size(), 4 * 4096u);
      EXPECT_GT(serialReport.EdgeRemovals, 500);
      EXPECT_GT(serialReport.Flips23, 5);
    }
    EXPECT_EQ(blockChanges, serialChanges);
    EXPECT_EQ(blockReport.EdgeRemovals, serialReport.EdgeRemovals);
    EXPECT_EQ(blockReport.Flips23, serialReport.Flips23);
    EXPECT_EQ(blockReport.EdgeSplits, serialReport.EdgeSplits);
    EXPECT_EQ(blockReport.FaceSplits, serialReport.FaceSplits);
    EXPECT_TRUE(serial.T == blocks.T) << "pass " << pass;
    EXPECT_TRUE(serial.Alive == blocks.Alive);
    EXPECT_TRUE(serial.Tried == blocks.Tried);
    EXPECT_TRUE(serialPoints == blockPoints);
    std::printf("pass %d: %ld edge removals, %ld 2-3 flips, %ld edge splits, %ld face splits\n", pass,
      serialReport.EdgeRemovals, serialReport.Flips23, serialReport.EdgeSplits, serialReport.FaceSplits);
  }
}
