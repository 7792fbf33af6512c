// The surface edge collapse of the sliver rounds (amTetraImproveCollapse.cxx), on a lattice cut
// in two regions by the plane z = 2 (its faces fixed, as are those of the lattice's boundary).
#include "amTetraGeometry.h"
#include "amTetraImproveMesh.h"
#include "amTetraLattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <unordered_map>
#include <vector>

namespace
{
using amTetraImprove::Sorted;
using amTetraImprove::Tet;
using amTetraImprove::Tri;
constexpr int N = 6;

int Id(int i, int j, int k)
{
  return (k * N + j) * N + i;
}

/// The lattice, region 2 above z = 2; its interface and boundary faces fixed.
void TwoRegions(std::vector<double>& p, amTetraImprove::Mesh& m, std::unordered_map<int, long>& count)
{
  amTest::Lattice(N, 0.0, p, m);
  std::map<Tri, int> seen;
  for (size_t t = 0; t < m.T.size(); ++t)
  {
    double z = 0;
    for (int v : m.T[t])
      z += p[3 * v + 2] / 4;
    m.R[t] = z > 2 ? 2 : 1;
    ++count[m.R[t]];
    for (int i = 0; i < 4; ++i)
      ++seen[Sorted(m.T[t][(i + 1) % 4], m.T[t][(i + 2) % 4], m.T[t][(i + 3) % 4])];
  }
  for (const auto& f : seen)
  {
    const bool onPlane = p[3 * f.first[0] + 2] == 2 && p[3 * f.first[1] + 2] == 2 && p[3 * f.first[2] + 2] == 2;
    if (f.second == 1 || onPlane)
    {
      m.FixedFaces.insert(f.first);
      for (int k = 0; k < 3; ++k)
      {
        m.FixedVertex[f.first[k]] = 1;
        m.FixedEdges.insert(amTetraImprove::EdgeKey(f.first[k], f.first[(k + 1) % 3]));
      }
    }
  }
}

std::map<int, double> Volumes(const amTetraImprove::Mesh& m)
{
  std::map<int, double> v;
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
      v[m.R[t]] += amTetraGeometry::SignedVolume(m.X(m.T[t][0]), m.X(m.T[t][1]), m.X(m.T[t][2]), m.X(m.T[t][3]));
  return v;
}

double PlaneArea(const amTetraImprove::Mesh& m)
{
  double area = 0;
  for (const Tri& f : m.FixedFaces)
    if (m.X(f[0])[2] == 2 && m.X(f[1])[2] == 2 && m.X(f[2])[2] == 2)
      area += 0.5 *
        amTetraGeometry::Norm(amTetraGeometry::Cross(
          amTetraGeometry::Sub(m.X(f[1]), m.X(f[0])), amTetraGeometry::Sub(m.X(f[2]), m.X(f[0]))));
  return area;
}
}

// A vertex of the interface slid next to its neighbour leaves flat elements that no flip can
// mend (all their vertices on the surface): collapsed onto the neighbour, along the plane, the
// surface keeps its place, the regions their volumes, and every element its orientation.
TEST(TetraImprove, CollapseAlongAnInterfaceKeepsItsPlace)
{
  std::vector<double> p;
  amTetraImprove::Mesh m(p);
  std::unordered_map<int, long> count;
  TwoRegions(p, m, count);
  const int v = Id(2, 2, 2), u = Id(3, 2, 2);
  const double near[3] = { 2.95, 2, 2 };
  amTetraImprove::MoveVertex(m, v, near);
  double worst = 1;
  for (int t : m.Inc[v])
    worst = std::min(worst, m.Objectives[t]);
  ASSERT_LT(worst, 0.1); // a sliver
  const std::map<int, double> before = Volumes(m);
  const size_t faces = m.FixedFaces.size();

  const double moved = amTetraImprove::CollapseSurfaceEdge(m, v, u, 0.01, count);
  ASSERT_GE(moved, 0);
  EXPECT_LT(moved, 1e-9);
  EXPECT_TRUE(m.Inc[v].empty());
  for (const Tri& f : m.FixedFaces)
    EXPECT_FALSE(f[0] == v || f[1] == v || f[2] == v);
  EXPECT_EQ(m.FixedFaces.size(), faces - 2); // the two interface faces on the edge
  EXPECT_NEAR(PlaneArea(m), (N - 1) * (N - 1), 1e-9);
  const std::map<int, double> after = Volumes(m);
  for (const auto& r : before)
    EXPECT_NEAR(after.at(r.first), r.second, 1e-9) << "region " << r.first;
  std::map<Tri, int> shared;
  worst = 1;
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
    {
      worst = std::min(worst, m.Objectives[t]);
      for (int i = 0; i < 4; ++i)
        ++shared[Sorted(m.T[t][(i + 1) % 4], m.T[t][(i + 2) % 4], m.T[t][(i + 3) % 4])];
    }
  EXPECT_GT(worst, 0.2);
  for (const auto& f : shared)
    EXPECT_LE(f.second, 2);
  EXPECT_EQ(count[1] + count[2], static_cast<long>(std::count(m.Alive.begin(), m.Alive.end(), 1)));
}

// Refused, the mesh left as it was: an edge off the surface, a vertex where the interface meets
// the boundary moved inside the interface (off its curve), and a move beyond the bound.
TEST(TetraImprove, CollapseRefusedOffTheCurveOrBeyondTheBound)
{
  std::vector<double> p;
  amTetraImprove::Mesh m(p);
  std::unordered_map<int, long> count;
  TwoRegions(p, m, count);
  const double near[3] = { 2.95, 2, 2 };
  amTetraImprove::MoveVertex(m, Id(2, 2, 2), near);
  const std::vector<Tet> tets = m.T;
  const std::vector<char> alive = m.Alive;
  const auto faces = m.FixedFaces;
  EXPECT_LT(amTetraImprove::CollapseSurfaceEdge(m, Id(2, 2, 2), Id(2, 2, 3), 1.0, count), 0);
  EXPECT_LT(amTetraImprove::CollapseSurfaceEdge(m, Id(0, 2, 2), Id(1, 2, 2), 1.0, count), 0);
  EXPECT_LT(amTetraImprove::CollapseSurfaceEdge(m, Id(2, 2, 2), Id(3, 2, 2), -1.0, count), 0);
  std::vector<Tet> aliveTets, aliveBefore;
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
      aliveTets.push_back(m.T[t]);
  for (size_t t = 0; t < tets.size(); ++t)
    if (alive[t])
      aliveBefore.push_back(tets[t]);
  std::sort(aliveTets.begin(), aliveTets.end());
  std::sort(aliveBefore.begin(), aliveBefore.end());
  EXPECT_TRUE(aliveTets == aliveBefore);
  EXPECT_TRUE(m.FixedFaces == faces);
}

// Relabel (amTetraImproveRelabel.cxx): an element with a face on the interface takes the region
// across it when the surface may move its thickness; the interface then runs over its other faces.
TEST(TetraImprove, RelabelMovesAnElementAcrossTheInterfaceWithinTheBound)
{
  std::vector<double> p;
  amTetraImprove::Mesh m(p);
  std::unordered_map<int, long> count;
  TwoRegions(p, m, count);
  // A region-1 element with a face on the plane z = 2, inside the lattice.
  int t = -1;
  Tri onPlane{};
  for (size_t k = 0; k < m.T.size() && t < 0; ++k)
  {
    if (m.R[k] != 1)
      continue;
    for (int i = 0; i < 4; ++i)
    {
      const Tri f = Sorted(m.T[k][(i + 1) % 4], m.T[k][(i + 2) % 4], m.T[k][(i + 3) % 4]);
      bool inside = true, plane = true;
      for (int v : f)
      {
        plane = plane && p[3 * v + 2] == 2;
        inside = inside && p[3 * v] > 0 && p[3 * v] < N - 1 && p[3 * v + 1] > 0 && p[3 * v + 1] < N - 1;
      }
      if (plane && inside)
      {
        t = static_cast<int>(k);
        onPlane = f;
      }
    }
  }
  ASSERT_GE(t, 0);
  const std::map<int, double> before = Volumes(m);
  const long one = count[1], two = count[2];
  // Beyond the bound (the element is a voxel's edge thick): refused, nothing changes.
  EXPECT_EQ(amTetraImprove::Relabel(m, t, 0.1, count), -1);
  EXPECT_EQ(m.R[t], 1);
  EXPECT_TRUE(m.FixedFaces.count(onPlane));
  const double moved = amTetraImprove::Relabel(m, t, 2.0, count);
  ASSERT_GT(moved, 0.1);
  EXPECT_LE(moved, 2.0);
  EXPECT_EQ(m.R[t], 2);
  EXPECT_FALSE(m.FixedFaces.count(onPlane)); // now inside region 2
  EXPECT_EQ(count[1], one - 1);
  EXPECT_EQ(count[2], two + 1);
  const std::map<int, double> after = Volumes(m);
  const double v = amTetraGeometry::SignedVolume(m.X(m.T[t][0]), m.X(m.T[t][1]), m.X(m.T[t][2]), m.X(m.T[t][3]));
  EXPECT_NEAR(after.at(1), before.at(1) - v, 1e-9);
  EXPECT_NEAR(after.at(2), before.at(2) + v, 1e-9);
  // Its other faces, towards region 1, are the interface now.
  for (int i = 0; i < 4; ++i)
  {
    const int s = m.Across(t, i);
    if (s >= 0 && m.R[s] == 1)
      EXPECT_TRUE(m.FixedFaces.count(Sorted(m.T[t][(i + 1) % 4], m.T[t][(i + 2) % 4], m.T[t][(i + 3) % 4])));
  }
}

// SplitSurfaceEdge (amTetraImproveSurfaceSplit.cxx): an edge of the interface split at its midpoint,
// every element and interface face on it in two, kept only when no element gets worse than the
// worst it replaces. On the regular lattice every half is worse than the whole: undone, the mesh as
// it was. An edge off the surface is not split.
TEST(TetraImprove, SplitSurfaceEdgeUndoneWhereItMakesAWorseElement)
{
  std::vector<double> p;
  amTetraImprove::Mesh m(p);
  std::unordered_map<int, long> count;
  TwoRegions(p, m, count);
  const int u = Id(2, 2, 2), v = Id(3, 2, 2); // an edge of the interface (the lattice's x edges are edges)
  ASSERT_TRUE(m.FixedEdges.count(amTetraImprove::EdgeKey(u, v)));
  const std::map<int, double> before = Volumes(m);
  const double area = PlaneArea(m);
  const size_t faces = m.FixedFaces.size(), alive = std::count(m.Alive.begin(), m.Alive.end(), 1);
  EXPECT_EQ(amTetraImprove::SplitSurfaceEdge(m, u, Id(2, 2, 1)), -1); // not a surface edge
  EXPECT_EQ(amTetraImprove::SplitSurfaceEdge(m, u, v), -1);
  EXPECT_TRUE(m.Connected(u, v));
  EXPECT_EQ(static_cast<size_t>(std::count(m.Alive.begin(), m.Alive.end(), 1)), alive);
  EXPECT_EQ(m.FixedFaces.size(), faces);
  EXPECT_NEAR(PlaneArea(m), area, 1e-9);
  const std::map<int, double> after = Volumes(m);
  for (const auto& r : before)
    EXPECT_NEAR(after.at(r.first), r.second, 1e-9) << "region " << r.first;
}

// Climb (amTetraImproveMoves.cxx): the local search moves a vertex up its star's worst quality; a
// vertex of the interface, with a bound, slides along the flat interface and stays within it.
TEST(TetraImprove, ClimbImprovesTheStarAndKeepsASurfaceVertexOnItsSurface)
{
  std::vector<double> p;
  amTetraImprove::Mesh m(p);
  std::unordered_map<int, long> count;
  TwoRegions(p, m, count);
  const auto worstOf = [&m](int v) {
    double worst = 1;
    for (int t : m.Inc[v])
      worst = std::min(worst, m.Objectives[t]);
    return worst;
  };
  const int free = Id(2, 2, 1), onPlane = Id(3, 3, 2);
  ASSERT_FALSE(m.FixedVertex[free]);
  ASSERT_TRUE(m.FixedVertex[onPlane]);
  const double off[3] = { 2.4, 2.3, 1.35 }, slid[3] = { 3.35, 3.3, 2.0 };
  amTetraImprove::MoveVertex(m, free, off);
  amTetraImprove::MoveVertex(m, onPlane, slid);
  const double freeBefore = worstOf(free), planeBefore = worstOf(onPlane);
  const std::map<int, double> before = Volumes(m);
  ASSERT_TRUE(amTetraImprove::Climb(m, free));
  EXPECT_GT(worstOf(free), freeBefore);
  m.Origin = m.P; // the surface as it is now: the bound is measured from it
  ASSERT_TRUE(amTetraImprove::Climb(m, onPlane, 0.01));
  EXPECT_GT(worstOf(onPlane), planeBefore);
  EXPECT_NEAR(m.X(onPlane)[2], 2.0, 0.01); // on the interface, within the bound
  const std::map<int, double> after = Volumes(m);
  for (const auto& r : before)
    EXPECT_NEAR(after.at(r.first), r.second, 0.02 * r.second) << "region " << r.first;
  for (int t : m.Inc[onPlane])
    EXPECT_GT(m.Objectives[t], 0); // nothing inverted
}
