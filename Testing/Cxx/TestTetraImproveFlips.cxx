// The topological operations of the element improvement (amTetraImproveFlips.cxx) on hand-made
// configurations: a 2-3 flip across a face and the edge removal (3-2) that undoes it, each taken
// only when the worst element it touches gets better.
#include "amTetraGeometry.h"
#include "amTetraImproveMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace
{
using amTetraImprove::Tet;

// Triangle a b c in the plane z = 0 and two apexes d (above, at height 'up') and e (below, at
// height 'down'), both over the point (0.3, 0.3) inside the triangle.
struct Bipyramid
{
  std::vector<double> P;
  amTetraImprove::Mesh M{ P };
  int A, B, C, D, E;
  Bipyramid(double up, double down)
  {
    const double x[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.3, 0.3, up }, { 0.3, 0.3, -down } };
    for (const auto& q : x)
      this->M.AddPoint(q);
    this->A = 0, this->B = 1, this->C = 2, this->D = 3, this->E = 4;
  }
  double SignedVolume(const Tet& t) const
  {
    return amTetraGeometry::SignedVolume(this->M.X(t[0]), this->M.X(t[1]), this->M.X(t[2]), this->M.X(t[3]));
  }
  // The live tetrahedra: their number, the smallest objective and signed volume, the total volume.
  void Live(int& count, double& worst, double& smallest, double& total) const
  {
    count = 0;
    worst = smallest = 1e30;
    total = 0;
    for (size_t t = 0; t < this->M.T.size(); ++t)
      if (this->M.Alive[t])
      {
        ++count;
        worst = std::min(worst, this->M.Objectives[t]);
        const double v = this->SignedVolume(this->M.T[t]);
        smallest = std::min(smallest, v);
        total += v;
      }
  }
};
}

TEST(TetraImproveFlips, Flip23ReplacesAFlatPairByThreeAroundTheApexes)
{
  // d just above the triangle: the upper tetrahedron is flat; the flip makes three about d-e.
  Bipyramid s(0.05, 1.0);
  const int t = s.M.Add({ s.D, s.A, s.C, s.B }, 1);
  const int other = s.M.Add({ s.E, s.A, s.B, s.C }, 1);
  ASSERT_GT(s.SignedVolume(s.M.T[t]), 0);
  ASSERT_GT(s.SignedVolume(s.M.T[other]), 0);
  int count;
  double worstBefore, smallest, volumeBefore;
  s.Live(count, worstBefore, smallest, volumeBefore);
  ASSERT_TRUE(amTetraImprove::Flip23(s.M, t, 0)); // the face opposite d, shared with e's tetrahedron
  double worst, volume;
  s.Live(count, worst, smallest, volume);
  EXPECT_EQ(count, 3);
  EXPECT_FALSE(s.M.Alive[t]);
  EXPECT_FALSE(s.M.Alive[other]);
  EXPECT_GT(worst, worstBefore);
  EXPECT_GT(smallest, 0); // every new element positively oriented
  EXPECT_NEAR(volume, volumeBefore, 1e-12);
  for (size_t k = 0; k < s.M.T.size(); ++k)
    if (s.M.Alive[k])
      EXPECT_TRUE(s.M.Has(static_cast<int>(k), s.D) && s.M.Has(static_cast<int>(k), s.E));
}

TEST(TetraImproveFlips, Flip23RefusedAcrossAFixedFaceAnotherRegionOrForTheWorse)
{
  {
    Bipyramid s(0.05, 1.0);
    const int t = s.M.Add({ s.D, s.A, s.C, s.B }, 1);
    s.M.Add({ s.E, s.A, s.B, s.C }, 1);
    s.M.FixedFaces.insert(amTetraImprove::Sorted(s.A, s.B, s.C)); // an interface: it stays
    EXPECT_FALSE(amTetraImprove::Flip23(s.M, t, 0));
  }
  {
    Bipyramid s(0.05, 1.0);
    const int t = s.M.Add({ s.D, s.A, s.C, s.B }, 1);
    s.M.Add({ s.E, s.A, s.B, s.C }, 2); // across a region boundary
    EXPECT_FALSE(amTetraImprove::Flip23(s.M, t, 0));
  }
  {
    // A regular-looking pair: three thin elements about the long edge d-e would be worse.
    Bipyramid s(2.0, 2.0);
    const int t = s.M.Add({ s.D, s.A, s.C, s.B }, 1);
    s.M.Add({ s.E, s.A, s.B, s.C }, 1);
    EXPECT_FALSE(amTetraImprove::Flip23(s.M, t, 0));
    int count;
    double worst, smallest, volume;
    s.Live(count, worst, smallest, volume);
    EXPECT_EQ(count, 2); // the mesh as it was
  }
}

TEST(TetraImproveFlips, EdgeRemovalUndoesAThinRingAndKeepsAFixedEdge)
{
  // Three elements about the long edge d-e (apexes far apart) are thin; removing the edge leaves the
  // two tetrahedra on the triangle, better.
  Bipyramid s(2.0, 2.0);
  s.M.Add({ s.D, s.E, s.B, s.A }, 1);
  s.M.Add({ s.D, s.E, s.C, s.B }, 1);
  s.M.Add({ s.D, s.E, s.A, s.C }, 1);
  int count;
  double worstBefore, smallest, volumeBefore;
  s.Live(count, worstBefore, smallest, volumeBefore);
  ASSERT_GT(smallest, 0);
  {
    Bipyramid fixed(2.0, 2.0);
    fixed.M.Add({ fixed.D, fixed.E, fixed.B, fixed.A }, 1);
    fixed.M.Add({ fixed.D, fixed.E, fixed.C, fixed.B }, 1);
    fixed.M.Add({ fixed.D, fixed.E, fixed.A, fixed.C }, 1);
    fixed.M.FixedEdges.insert(amTetraImprove::EdgeKey(fixed.D, fixed.E)); // on a junction curve: it stays
    std::vector<int> tets, ring;
    EXPECT_FALSE(amTetraImprove::RemoveEdge(fixed.M, fixed.D, fixed.E, 7, tets, ring));
  }
  std::vector<int> tets, ring;
  // The edge's ring is closed only with the triangle's three vertices around it: no more than 3.
  EXPECT_FALSE(amTetraImprove::RemoveEdge(s.M, s.D, s.E, 2, tets, ring));
  ASSERT_TRUE(amTetraImprove::RemoveEdge(s.M, s.D, s.E, 7, tets, ring));
  EXPECT_EQ(tets.size(), 3u);
  EXPECT_EQ(ring.size(), 3u);
  double worst, volume;
  s.Live(count, worst, smallest, volume);
  EXPECT_EQ(count, 2);
  EXPECT_GT(worst, worstBefore);
  EXPECT_GT(smallest, 0);
  EXPECT_NEAR(volume, volumeBefore, 1e-12);
  EXPECT_FALSE(s.M.Connected(s.D, s.E));
}

TEST(TetraImproveFlips, EdgeRemovalRefusesAChordTheMeshHasAlready)
{
  // Four thin elements about the long edge d-e with the square a b c f around it: removing the
  // edge would triangulate the square by a diagonal. Where both diagonals are edges of the mesh
  // already (elements outside the ring hold them), the new elements would fold over theirs: the
  // edge stays.
  for (const bool diagonalsTaken : { false, true })
  {
    std::vector<double> p;
    amTetraImprove::Mesh m(p);
    const double x[][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 2 }, { 0, 0, -2 },
      { 5, 5, 5 }, { 6, 5, 5 }, { 5, 6, 5 } };
    for (const auto& q : x)
      m.AddPoint(q);
    const int d = 4, e = 5;
    auto add = [&](Tet t) {
      if (amTetraGeometry::SignedVolume(m.X(t[0]), m.X(t[1]), m.X(t[2]), m.X(t[3])) < 0)
        std::swap(t[2], t[3]);
      m.Add(t, 1);
    };
    for (int k = 0; k < 4; ++k)
      add({ d, e, k, (k + 1) % 4 });
    if (diagonalsTaken)
    {
      add({ 0, 2, 6, 7 });
      add({ 1, 3, 6, 8 });
    }
    std::vector<int> tets, ring;
    EXPECT_EQ(amTetraImprove::RemoveEdge(m, d, e, 7, tets, ring), !diagonalsTaken);
    EXPECT_EQ(m.Connected(d, e), diagonalsTaken);
    EXPECT_EQ(amTetraImprove::FoldedFaces(m), 0);
  }
}

TEST(TetraImproveFlips, FoldedFacesFindsThreeOnAFaceAndTwoOnOneSide)
{
  Bipyramid s(1.0, 1.0);
  s.M.Add({ s.D, s.A, s.C, s.B }, 1);
  s.M.Add({ s.E, s.A, s.B, s.C }, 1);
  EXPECT_EQ(amTetraImprove::FoldedFaces(s.M), 0);
  // A second apex above the triangle: two elements on its upper side.
  const double up[3] = { 0.2, 0.2, 0.5 };
  const int w = s.M.AddPoint(up);
  s.M.Add({ w, s.A, s.C, s.B }, 1);
  EXPECT_EQ(amTetraImprove::FoldedFaces(s.M), 1);
}
