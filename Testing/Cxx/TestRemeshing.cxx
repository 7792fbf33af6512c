// The remesher's parts on hand-made surfaces: each guard, operation, the bins, the scheduler and
// the Hausdorff measure on its own, with answers known in advance.
#include "amRemeshScheduler.h"
#include "amRemesher.h"

#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

using namespace amRemesh;

namespace
{
/// A flat n x n grid of squares of side h in z = 0, each split along its diagonal from (i, j)
/// to (i + 1, j + 1), normals +z; labels (label, 0) when label >= 0. Vertex (i, j) is j (n + 1) + i.
amSurfaceMesh FlatGrid(int n, double h, int label = -1)
{
  amSurfaceMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      m.Points.push_back({ i * h, j * h, 0.0 });
  auto id = [n](int i, int j) { return static_cast<vtkIdType>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      m.Triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.Triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
      if (label >= 0)
        m.Labels.insert(m.Labels.end(), 2, { label, 0 });
    }
  m.BuildTopology();
  return m;
}

/// A grid of 0.5 mm squares, 12 mm across, over a smooth bump 2 mm high (label 1).
amSurfaceMesh BumpyPatch()
{
  amSurfaceMesh m = FlatGrid(24, 0.5, 1);
  for (auto& p : m.Points)
  {
    const double dx = p[0] - 6, dy = p[1] - 6;
    p[2] = 2.0 * std::exp(-(dx * dx + dy * dy) / 8.0);
  }
  m.BuildTopology();
  return m;
}

int Vertex(int n, int i, int j)
{
  return j * (n + 1) + i;
}

/// A remesher set up on m with a uniform metric of edge length 'size' and tolerance eps, its
/// bins built (as the driver builds them before each iteration).
std::unique_ptr<Remesher> Start(const amSurfaceMesh& m, double eps, double size)
{
  auto r = std::make_unique<Remesher>();
  r->Setup(m, std::vector<Mat3>(m.Points.size(), Mat3::Identity() / (size * size)), eps);
  r->Grid.Rebuild();
  return r;
}

long long LiveTriangles(const Surface& s)
{
  long long n = 0;
  for (const Triangle& t : s.T)
    n += t.Alive;
  return n;
}

/// Every live edge has at most two triangles, and both run it in opposite directions.
void ExpectOrientedManifold(const Surface& s)
{
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : s.T)
    if (t.Alive)
      for (int k = 0; k < 3; ++k)
        ++directed[{ t.V[k], t.V[(k + 1) % 3] }];
  for (const auto& [e, count] : directed)
    EXPECT_EQ(count, 1) << "edge " << e.first << "-" << e.second << " run twice the same way";
}

/// Whether two surface states are the same: positions, triangles, stars.
bool Same(const Surface& a, const Surface& b)
{
  if (a.P.size() != b.P.size() || a.T.size() != b.T.size() || a.VT != b.VT || a.VAlive != b.VAlive)
    return false;
  for (size_t v = 0; v < a.P.size(); ++v)
    if (!(a.P[v] == b.P[v]))
      return false;
  for (size_t t = 0; t < a.T.size(); ++t)
  {
    const Triangle &x = a.T[t], &y = b.T[t];
    if (x.Alive != y.Alive || x.Sheet != y.Sheet || x.Labels[0] != y.Labels[0] || x.Labels[1] != y.Labels[1] ||
      !std::equal(x.V, x.V + 3, y.V))
      return false;
  }
  return true;
}

/// Every live triangle is listed once in each bin of its range and nowhere else; no bin lists a
/// dead triangle.
void ExpectExactBins(const Remesher& r)
{
  std::map<std::pair<int, long long>, std::multiset<int>> listed;
  for (int zone = 0; zone < 3; ++zone)
    r.Grid.Map[zone].ForEach([&](long long key, const std::vector<int>& list) {
      for (int t : list)
      {
        EXPECT_TRUE(r.Mesh.T[t].Alive) << "dead triangle " << t << " still binned";
        listed[{ zone, key }].insert(t);
      }
    });
  size_t expected = 0;
  for (size_t t = 0; t < r.Mesh.T.size(); ++t)
    if (r.Mesh.T[t].Alive)
    {
      const std::array<int, 6> range = r.Grid.Range(static_cast<int>(t));
      EXPECT_EQ(range, r.Grid.BinnedIn[t]) << "triangle " << t;
      r.Grid.ForRange(range, nullptr, [&](long long key, int zone) {
        ++expected;
        EXPECT_EQ((listed[{ zone, key }].count(static_cast<int>(t))), 1u) << "triangle " << t;
      });
    }
  size_t entries = 0;
  for (const auto& [bin, ts] : listed)
    entries += ts.size();
  EXPECT_EQ(entries, expected);
}
}

TEST(RemeshCrossingGuard, PairsThatCrossFoldOrStayApart)
{
  const std::array<int, 3> a = { 0, 1, 2 };
  const std::array<Vec3, 3> pa = { Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0) };
  // Through the middle of a: crosses; lifted above it: apart.
  const std::array<int, 3> b = { 3, 4, 5 };
  const Vec3 through[3] = { Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), Vec3(1.5, -1, 0.2) };
  const Vec3 above[3] = { Vec3(0.5, 0.5, 1), Vec3(0.5, 0.5, 2), Vec3(1.5, -1, 1.2) };
  EXPECT_TRUE(CrossingGuard::PairCrosses(a, pa, b, through));
  EXPECT_FALSE(CrossingGuard::PairCrosses(a, pa, b, above));
  // On a's edge (0, 1): folded flat onto a (well under a degree) counts; opposite or at an
  // angle does not.
  const std::array<int, 3> c = { 1, 0, 6 };
  const Vec3 folded[3] = { Vec3(2, 0, 0), Vec3(0, 0, 0), Vec3(0.5, 2, 0.001) };
  const Vec3 opposite[3] = { Vec3(2, 0, 0), Vec3(0, 0, 0), Vec3(0.5, -2, 0) };
  const Vec3 steep[3] = { Vec3(2, 0, 0), Vec3(0, 0, 0), Vec3(0.5, 2, 1) };
  EXPECT_TRUE(CrossingGuard::PairCrosses(a, pa, c, folded));
  EXPECT_FALSE(CrossingGuard::PairCrosses(a, pa, c, opposite));
  EXPECT_FALSE(CrossingGuard::PairCrosses(a, pa, c, steep));
}

TEST(RemeshCrossingGuard, RefusesNewTrianglesThroughLiveOnes)
{
  const amSurfaceMesh m = FlatGrid(6, 1.0);
  auto r = Start(m, 0.1, 1.0);
  Worker& w = r->W();
  // A vertical triangle through the grid near (2.5, 2.5), with vertices of its own.
  const std::vector<std::array<int, 3>> ids = { { 1000, 1001, 1002 } };
  const std::vector<std::array<Vec3, 3>> through = { { Vec3(2.4, 2.5, -1), Vec3(2.6, 2.5, -1), Vec3(2.5, 2.5, 1) } };
  const std::vector<std::array<Vec3, 3>> above = { { Vec3(2.4, 2.5, 0.5), Vec3(2.6, 2.5, 0.5), Vec3(2.5, 2.5, 1) } };
  EXPECT_TRUE(r->Crossing.Crosses(ids, through, {}, w));
  ASSERT_GE(w.LastHit, 0);
  EXPECT_TRUE(r->Mesh.T[w.LastHit].Alive);
  EXPECT_FALSE(r->Crossing.Crosses(ids, above, {}, w));
  // Triangles about to be removed are not in the way: every triangle the vertical one crosses.
  std::vector<int> removed;
  while (r->Crossing.Crosses(ids, through, removed, w) && w.LastHit >= 0)
    removed.push_back(w.LastHit);
  EXPECT_FALSE(r->Crossing.Crosses(ids, through, removed, w));
  EXPECT_GE(removed.size(), 1u);
  EXPECT_LE(removed.size(), 4u);
  // A new triangle of no area is refused like a crossing.
  const std::vector<std::array<Vec3, 3>> flat = { { Vec3(1, 1, 1), Vec3(2, 2, 1), Vec3(3, 3, 1) } };
  EXPECT_TRUE(r->Crossing.Crosses(ids, flat, {}, w));
}

TEST(RemeshCrossingGuard, InsideASweptTetrahedron)
{
  const std::array<Vec3, 4> t = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1) };
  EXPECT_TRUE(CrossingGuard::StrictlyInside(t, Vec3(0.2, 0.2, 0.2)));
  EXPECT_FALSE(CrossingGuard::StrictlyInside(t, Vec3(0.5, 0.5, 0.5))); // outside
  EXPECT_FALSE(CrossingGuard::StrictlyInside(t, Vec3(0.3, 0.3, 0.0))); // on a face
  EXPECT_FALSE(CrossingGuard::StrictlyInside(t, Vec3(0, 0, 0)));       // a corner
  const std::array<Vec3, 4> flat = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0) };
  EXPECT_FALSE(CrossingGuard::StrictlyInside(flat, Vec3(0.5, 0.5, 0.0))); // no inside
}

TEST(RemeshCrossingGuard, RefusesAMoveThatTurnsARegionInsideOut)
{
  // A one-voxel region: the unit cube, its two opposite corners A = (0,0,0) and B = (1,1,1) each
  // the apex of the six triangles of their three faces, normals out of region 1.
  amSurfaceMesh m;
  for (int k = 0; k < 8; ++k)
    m.Points.push_back({ double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1) });
  const vtkIdType A = 0, B = 7;
  // Around A the faces x = 0, y = 0, z = 0; around B the faces x = 1, y = 1, z = 1.
  m.Triangles = { { A, 4, 6 }, { A, 6, 2 }, { A, 1, 5 }, { A, 5, 4 }, { A, 2, 3 }, { A, 3, 1 }, { B, 5, 1 },
    { B, 1, 3 }, { B, 3, 2 }, { B, 2, 6 }, { B, 6, 4 }, { B, 4, 5 } };
  m.Labels.assign(m.Triangles.size(), { 1, 0 });
  m.BuildTopology();
  auto r = Start(m, 10.0, 10.0);
  ASSERT_GT(r->RegionVolumes()[1], 0.99);
  const Vec3 c(0.5, 0.5, 0.5), diagonal(1, 1, 1);
  // A just short of the centre: the region keeps a positive volume.
  ASSERT_TRUE(r->Move(A, c - 0.01 * diagonal, false));
  EXPECT_GT(r->RegionVolumes()[1], 0.0);
  // B halfway, then past A: no triangle would cross another at the end, but the region would
  // enclose a negative volume; B's triangles pass through A on the way. (In one step the
  // triangles would turn too far: the guard on normals refuses that.)
  ASSERT_TRUE(r->Move(B, c + 0.2 * diagonal, false));
  const Remesher::Snapshot before = r->Save();
  EXPECT_FALSE(r->Move(B, c - 0.03 * diagonal, false));
  EXPECT_TRUE(Same(before.Mesh, r->Mesh));
  // B to the centre's other side of A is fine.
  EXPECT_TRUE(r->Move(B, c + 0.03 * diagonal, false));
  EXPECT_GT(r->RegionVolumes()[1], 0.0);
}

TEST(RemeshCollapse, ShortEdgeCollapsesAndTheSurfaceStaysValid)
{
  const int n = 6;
  const amSurfaceMesh m = FlatGrid(n, 1.0);
  auto r = Start(m, 0.1, 3.0);
  const int a = Vertex(n, 2, 2), b = Vertex(n, 3, 2);
  const long long before = LiveTriangles(r->Mesh);
  ASSERT_TRUE(r->Collapse(a, b));
  EXPECT_FALSE(r->Mesh.VAlive[a]);
  EXPECT_TRUE(r->Mesh.VT[a].empty());
  EXPECT_EQ(LiveTriangles(r->Mesh), before - 2);
  EXPECT_EQ(r->Collapses(), 1);
  // b now stands for a's input point too.
  EXPECT_EQ(r->Mesh.Cluster[b].size(), 2u);
  ExpectOrientedManifold(r->Mesh);
  ExpectExactBins(*r);
  // Not an edge any more: refused.
  EXPECT_FALSE(r->Collapse(a, b));
  EXPECT_FALSE(r->Collapse(Vertex(n, 0, 0), Vertex(n, 5, 5)));
}

TEST(RemeshCollapse, FoldIsRefusedAndNothingChanges)
{
  const int n = 6;
  const amSurfaceMesh m = FlatGrid(n, 1.0);
  auto r = Start(m, 10.0, 10.0);
  const int a = Vertex(n, 2, 2), b = Vertex(n, 3, 2);
  const Remesher::Snapshot before = r->Save();
  // Both ends moved three edges beyond b: b's triangles on the far side turn over.
  const Vec3 far = r->Mesh.P[a] + 4.0 * (r->Mesh.P[b] - r->Mesh.P[a]);
  EXPECT_FALSE(r->Collapse(a, b, &far));
  EXPECT_TRUE(Same(before.Mesh, r->Mesh));
  EXPECT_EQ(r->Collapses(), 0);
  // The same edge into its middle is fine.
  const Vec3 middle = 0.5 * (r->Mesh.P[a] + r->Mesh.P[b]);
  EXPECT_TRUE(r->Collapse(a, b, &middle));
  ExpectOrientedManifold(r->Mesh);
}

TEST(RemeshCollapse, ToleranceRefusesACollapseThatLeavesTheInput)
{
  const int n = 6;
  amSurfaceMesh m = FlatGrid(n, 1.0);
  const int a = Vertex(n, 2, 2), b = Vertex(n, 3, 2);
  m.Points[a][2] = 1.0; // a peak: flattening it moves the surface up to 1 mm from the input
  m.BuildTopology();
  EXPECT_FALSE(Start(m, 0.1, 3.0)->Collapse(a, b));
  EXPECT_TRUE(Start(m, 2.0, 3.0)->Collapse(a, b));
}

TEST(RemeshFlip, FlipImprovesAnglesAndKeepsLabels)
{
  // A flat rhombus split along its long diagonal (a, b): smallest angle 14 degrees; split along
  // (c, d) instead: 28 degrees.
  amSurfaceMesh m;
  m.Points = { { -2, 0, 0 }, { 2, 0, 0 }, { 0, 0.5, 0 }, { 0, -0.5, 0 } };
  m.Triangles = { { 0, 1, 2 }, { 1, 0, 3 } };
  m.Labels = { { 5, 0 }, { 5, 0 } };
  m.BuildTopology();
  auto r = Start(m, 0.1, 1.0);
  ASSERT_TRUE(r->Flip(0, 1));
  EXPECT_EQ(r->Flips(), 1);
  std::set<std::set<int>> now;
  for (const Triangle& t : r->Mesh.T)
  {
    ASSERT_TRUE(t.Alive); // a flip keeps both triangles' slots
    EXPECT_EQ(t.Labels[0], 5);
    EXPECT_EQ(t.Labels[1], 0);
    now.insert({ t.V[0], t.V[1], t.V[2] });
    EXPECT_GT(r->Mesh.Normal(static_cast<int>(&t - r->Mesh.T.data())).z(), 0);
  }
  EXPECT_EQ(now, (std::set<std::set<int>>{ { 0, 3, 2 }, { 3, 1, 2 } }));
  // Flipping back would make the angles worse: refused.
  EXPECT_FALSE(r->Flip(2, 3));

  // The same rhombus as two interfaces (labels 5 and 6): the edge is a junction curve and stays.
  m.Labels = { { 5, 0 }, { 6, 0 } };
  m.BuildTopology();
  auto junction = Start(m, 0.1, 1.0);
  EXPECT_FALSE(junction->Flip(0, 1));
}

TEST(RemeshSplit, SplitEdgeAndInsertKeepTheSurfaceValid)
{
  const int n = 4;
  const amSurfaceMesh m = FlatGrid(n, 1.0, 3);
  auto r = Start(m, 0.1, 1.0);
  const size_t vertices = r->Mesh.P.size();
  const long long triangles = LiveTriangles(r->Mesh);
  // Triangle 2 (1 + 1) is (1, 1)-(2, 1)-(2, 2); its edge 0 is inside the grid.
  const int t = 2 * (n + 1);
  const Vec3 mid = 0.5 * (r->Mesh.P[r->Mesh.T[t].V[0]] + r->Mesh.P[r->Mesh.T[t].V[1]]);
  ASSERT_TRUE(r->SplitEdge(t, 0, mid));
  EXPECT_EQ(r->Mesh.P.size(), vertices + 1);
  EXPECT_EQ(LiveTriangles(r->Mesh), triangles + 2);
  EXPECT_EQ(r->Mesh.Kind.back(), amSurfaceMesh::Surface);
  ExpectOrientedManifold(r->Mesh);
  ExpectExactBins(*r);
  // Inserting at a live triangle's centroid: one vertex and two triangles more.
  int live = -1;
  for (size_t s = 0; s < r->Mesh.T.size() && live < 0; ++s)
    if (r->Mesh.T[s].Alive)
      live = static_cast<int>(s);
  const Triangle& tri = r->Mesh.T[live];
  const Vec3 centroid = (r->Mesh.P[tri.V[0]] + r->Mesh.P[tri.V[1]] + r->Mesh.P[tri.V[2]]) / 3.0;
  ASSERT_TRUE(r->Insert(live, centroid));
  EXPECT_EQ(r->Mesh.P.size(), vertices + 2);
  EXPECT_EQ(LiveTriangles(r->Mesh), triangles + 4);
  for (const Triangle& s : r->Mesh.T)
    if (s.Alive)
      EXPECT_EQ(s.Labels[0], 3);
  ExpectOrientedManifold(r->Mesh);
  ExpectExactBins(*r);
}

TEST(RemeshApproximationGuard, BoundHoldsOnAPlane)
{
  const int n = 4;
  const amSurfaceMesh m = FlatGrid(n, 1.0);
  auto r = Start(m, 0.1, 1.0);
  const Input& in = r->In;
  const Vec3 up(0, 0, 1);
  EXPECT_TRUE(in.TriangleNear(0, Vec3(1, 1, 0.05), Vec3(2, 1, 0.05), Vec3(1, 2, 0.05)));
  EXPECT_FALSE(in.TriangleNear(0, Vec3(1, 1, 0.15), Vec3(2, 1, 0.15), Vec3(1, 2, 0.15)));
  // Corners on the input, the middle of the triangle bulging out: the centroid is what is far.
  EXPECT_FALSE(in.TriangleNear(0, Vec3(1, 1, 0), Vec3(3, 1, 0.5), Vec3(1, 3, -0.5)) &&
    in.Near(0, Vec3(5.0 / 3, 5.0 / 3, 0.5), up));
  // A vertex moved off the plane by half the tolerance keeps its input point within reach; by
  // five times it does not.
  const int v = Vertex(n, 2, 2);
  std::vector<int> ring;
  r->Mesh.Neighbours(v, ring);
  ring.push_back(v);
  for (double dz : { 0.05, 0.5 })
  {
    std::vector<std::array<int, 3>> ids;
    std::vector<std::array<Vec3, 3>> pos;
    std::vector<int> sheets;
    for (int t : r->Mesh.VT[v])
    {
      std::array<int, 3> id;
      std::array<Vec3, 3> p;
      for (int k = 0; k < 3; ++k)
      {
        id[k] = r->Mesh.T[t].V[k];
        p[k] = r->Mesh.P[id[k]] + (id[k] == v ? Vec3(0, 0, dz) : Vec3::Zero());
      }
      ids.push_back(id);
      pos.push_back(p);
      sheets.push_back(0);
    }
    Worker& w = r->W();
    const bool ok = r->Approximation.ClustersStayNear(r->Mesh.VT[v], ids, pos, sheets, r->Mesh.VT[v], ring, w);
    EXPECT_EQ(ok, dz < 0.1) << dz;
    EXPECT_EQ(r->Approximation.StarNear(ids, pos, sheets, v, {}), dz < 0.1) << dz;
    if (ok)
    {
      EXPECT_FALSE(w.PendingHints.empty());
      r->Approximation.KeepHints(w);
      EXPECT_TRUE(w.PendingHints.empty());
      EXPECT_GE(r->Mesh.Cluster[v][0].Hint, 0);
    }
  }
}

TEST(RemeshHausdorffMeasure, MeasuresALiftedVertex)
{
  const int n = 4;
  const amSurfaceMesh m = FlatGrid(n, 1.0);
  auto r = Start(m, 0.1, 1.0);
  double upper = -1;
  std::vector<std::pair<int, Vec3>> insert;
  std::vector<int> edgeOf;
  EXPECT_NEAR(r->Hausdorff.Measure(r->Mesh, r->In, upper, insert, edgeOf), 0.0, 1e-12);
  EXPECT_TRUE(insert.empty());
  // One vertex lifted by 0.3: the result is 0.3 from the input there (at the vertex itself).
  const int v = Vertex(n, 2, 2);
  r->Mesh.P[v].z() += 0.3;
  const double h = r->Hausdorff.Measure(r->Mesh, r->In, upper, insert, edgeOf);
  EXPECT_NEAR(h, 0.3, 1e-12);
  EXPECT_GE(upper, h);
  ASSERT_FALSE(insert.empty());
  EXPECT_EQ(insert.size(), edgeOf.size());
  for (const auto& [t, x] : insert)
  {
    const int* w = r->Mesh.T[t].V;
    EXPECT_TRUE(w[0] == v || w[1] == v || w[2] == v) << "triangle " << t << " is not at the lifted vertex";
    EXPECT_NEAR(x.z(), 0.0, 1e-12); // the point to insert lies on the input
  }
  // Measured again with nothing changed (from the cache): the same answer.
  std::vector<std::pair<int, Vec3>> again;
  double upperAgain;
  EXPECT_EQ(r->Hausdorff.Measure(r->Mesh, r->In, upperAgain, again, edgeOf), h);
  EXPECT_EQ(upperAgain, upper);
  EXPECT_EQ(again.size(), insert.size());
}

TEST(RemeshHausdorffMeasure, ClosedStripCountsItsTwoRegions)
{
  // Input: a flat 4 x 4 grid of unit squares; square (0, 0) separates regions 5 and 6, the rest
  // of column 0 regions 5 and 0, everything else regions 6 and 0.
  const int n = 4;
  amSurfaceMesh m = FlatGrid(n, 1.0, 6);
  for (int j = 0; j < n; ++j)
    for (int half = 0; half < 2; ++half)
      m.Labels[2 * (j * n) + half] = { 5, j == 0 ? 6 : 0 };
  auto r = Start(m, 1.2, 1.0);
  double upper;
  std::vector<std::pair<int, Vec3>> insert;
  std::vector<int> edgeOf;
  EXPECT_NEAR(r->Hausdorff.Measure(r->Mesh, r->In, upper, insert, edgeOf), 0.0, 1e-12);
  // The 5|6 interface closed (square (0, 0) now between 5 and 0, as when a strip between two
  // junction curves is zipped): no triangle of 5|6 is left, but regions 5 and 6 both still lie
  // within 1 of each of its samples (6 across the edge x = 1), so the distance is 1, not inf.
  const int sheet50 = r->Mesh.T[2 * n].Sheet; // square (0, 1)
  for (int half = 0; half < 2; ++half)
  {
    Triangle& t = r->Mesh.T[half];
    t.Labels[0] = 5;
    t.Labels[1] = 0;
    t.Sheet = sheet50;
  }
  const double h = r->Hausdorff.Measure(r->Mesh, r->In, upper, insert, edgeOf);
  EXPECT_NEAR(h, 1.0, 1e-9);
  EXPECT_TRUE(insert.empty()); // within the tolerance 1.2: nothing to refine
}

TEST(RemeshLabelOrder, RegionsAlternateAroundAJunctionEdge)
{
  // Three interfaces meet at the edge b-w (b at the origin, w on +z), at 0, 120 and 240 degrees;
  // regions 1, 2 and 3 lie between them. Vertex 5 lies at 300 degrees.
  amSurfaceMesh m;
  m.Points = { { 0, 0, 0 }, { 0, 0, 1 } };
  for (double degrees : { 0.0, 120.0, 240.0, 300.0 })
    m.Points.push_back({ std::cos(degrees * M_PI / 180), std::sin(degrees * M_PI / 180), 0.5 });
  // Each triangle runs b -> w -> third: its Labels[1] side is the way the angle grows.
  m.Triangles = { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 1, 4 } };
  m.Labels = { { 3, 1 }, { 1, 2 }, { 2, 3 } };
  m.BuildTopology();
  auto r = Start(m, 0.1, 1.0);
  const Vec3 b = r->Mesh.P[0];
  EXPECT_TRUE(r->LabelsInOrderAround(0, b, {}, {}, {}));
  // The 1|2 interface swung round past the 2|3 one (to 300 degrees): regions interleave.
  EXPECT_FALSE(r->LabelsInOrderAround(0, b, {}, { 1 }, { { 0, 1, 5 } }));
  // Swung less far (to 120 degrees again, by way of the same vertex): still in order.
  EXPECT_TRUE(r->LabelsInOrderAround(0, b, {}, { 1 }, { { 0, 1, 3 } }));
  // One interface gone: two triangles around the edge cannot interleave.
  EXPECT_TRUE(r->LabelsInOrderAround(0, b, { 2 }, { 1 }, { { 0, 1, 5 } }));
}

TEST(RemeshScheduler, EveryItemOnceWhateverTheThreads)
{
  for (const char* backend : { "STDThread", "Sequential" })
  {
    vtkSMPTools::SetBackend(backend);
    Surface s;
    const size_t n = 1000;
    std::vector<std::atomic<int>> calls(n), done(n);
    std::atomic<int> wrongZone(0);
    auto zoneOf = [](size_t i) { return static_cast<int>(i % 3); };
    const int total = OnTwoWorkers(s, n, zoneOf, [&](size_t i) {
      ++calls[i];
      if (CurrentZone() >= 0 && CurrentZone() != zoneOf(i))
        ++wrongZone;
      if (CurrentZone() >= 0 && i % 7 == 0)
        return -1; // left for the serial pass
      ++done[i];
      return i % 5 == 0 ? 0 : 1;
    });
    int expected = 0;
    for (size_t i = 0; i < n; ++i)
    {
      EXPECT_EQ(done[i], 1) << i;
      EXPECT_EQ(calls[i], (i % 3 < 2 && i % 7 == 0) ? 2 : 1) << i;
      expected += i % 5 != 0;
    }
    EXPECT_EQ(total, expected) << backend;
    EXPECT_EQ(wrongZone, 0);
    EXPECT_EQ(CurrentZone(), -1);
    EXPECT_EQ(CurrentWorker(), 0);
  }
  vtkSMPTools::SetBackend("STDThread");
}

TEST(RemeshJunctionCurves, CurveMiddleIsHalfwayAlongTheCurve)
{
  JunctionCurves curves;
  // A polyline 0 - 1 - 2 - 3 - 4 with edges of 1, 1, 2, 1 mm.
  curves.CurveNeighbours.resize(5);
  const double length[4] = { 1, 1, 2, 1 };
  for (int v = 0; v < 4; ++v)
  {
    curves.CurveNeighbours[v].push_back({ v + 1, length[v] });
    curves.CurveNeighbours[v + 1].push_back({ v, length[v] });
  }
  EXPECT_EQ(curves.CurveMiddle(0, 4, 10), 2); // 2.5 along 5: vertex 2 is at 2
  EXPECT_EQ(curves.CurveMiddle(4, 0, 10), 2); // 2.5 along from the other end: 3 (at 1) or 2 (at 3)
  EXPECT_EQ(curves.CurveMiddle(0, 2, 10), 1);
  EXPECT_EQ(curves.CurveMiddle(0, 1, 10), -1); // no vertex between
  EXPECT_EQ(curves.CurveMiddle(0, 4, 4), -1);  // the curve is longer than allowed
}

TEST(RemeshBins, StayExactThroughChanges)
{
  const int n = 8;
  const amSurfaceMesh m = FlatGrid(n, 1.0);
  auto r = Start(m, 0.1, 3.0);
  ExpectExactBins(*r);
  // The split plane: across the longest side at the median vertex; every zone is used.
  size_t inZone[3] = { 0, 0, 0 };
  for (int zone = 0; zone < 3; ++zone)
    inZone[zone] = r->Grid.Map[zone].Size();
  EXPECT_GT(inZone[0], 0u);
  EXPECT_GT(inZone[1], 0u);
  // A vertex moved by hand, its star binned again; then a triangle removed.
  const int v = Vertex(n, 4, 4);
  r->Mesh.P[v] += Vec3(3.3, 0.2, 0);
  r->Grid.Update(r->Mesh.VT[v]);
  ExpectExactBins(*r);
  r->Detach(r->Mesh.VT[v][0]);
  ExpectExactBins(*r);
  // A collapse pass changes many triangles; the bins follow them.
  r->Mesh.P[v] -= Vec3(3.3, 0.2, 0);
  r->Grid.Rebuild();
  EXPECT_GT(r->CollapsePass(), 0);
  ExpectExactBins(*r);
}

TEST(RemeshUndo, RestoreGivesTheSavedSurface)
{
  const int n = 8;
  const amSurfaceMesh m = FlatGrid(n, 1.0, 2);
  auto r = Start(m, 0.1, 3.0);
  const Remesher::Snapshot before = r->Save();
  Remesher::Snapshot kept = r->Save();
  ASSERT_GT(r->CollapsePass(), 0);
  r->FlipPass();
  EXPECT_FALSE(Same(before.Mesh, r->Mesh));
  EXPECT_GT(r->Collapses(), 0);
  r->Restore(std::move(kept));
  EXPECT_TRUE(Same(before.Mesh, r->Mesh));
  EXPECT_EQ(r->Collapses(), 0);
}

TEST(RemeshCompact, DropsTheDeadAndKeepsTheOrder)
{
  // A bumpy patch collapsed once, then compacted: the live vertices and triangles renumbered in
  // their order, stars and clusters following them, the bins exact, and what follows (flips,
  // relaxation, the bound enforced) the same surface as on a copy that was not compacted.
  const int n = 16;
  amSurfaceMesh m = FlatGrid(n, 0.5, 1);
  for (auto& p : m.Points)
    p[2] = std::exp(-((p[0] - 4) * (p[0] - 4) + (p[1] - 4) * (p[1] - 4)) / 4.0);
  m.BuildTopology();
  auto a = Start(m, 0.05, 2.0), b = Start(m, 0.05, 2.0);
  ASSERT_GT(a->CollapsePass(), 0);
  ASSERT_EQ(b->CollapsePass(), a->Collapses());
  std::vector<std::array<int, 3>> corners; // live triangles as old vertex ids
  std::vector<int> liveVertices;
  for (size_t v = 0; v < a->Mesh.P.size(); ++v)
    if (a->Mesh.VAlive[v])
      liveVertices.push_back(static_cast<int>(v));
  for (const Triangle& t : a->Mesh.T)
    if (t.Alive)
      corners.push_back({ t.V[0], t.V[1], t.V[2] });
  ASSERT_LT(liveVertices.size(), a->Mesh.P.size());
  const Surface before = a->Mesh;
  a->Compact();
  const Surface& s = a->Mesh;
  ASSERT_EQ(s.P.size(), liveVertices.size());
  ASSERT_EQ(s.T.size(), corners.size());
  for (size_t v = 0; v < s.P.size(); ++v)
  {
    const int old = liveVertices[v];
    EXPECT_EQ(s.P[v], before.P[old]);
    EXPECT_EQ(s.Kind[v], before.Kind[old]);
    EXPECT_TRUE(s.VAlive[v]);
    ASSERT_EQ(s.Cluster[v].size(), before.Cluster[old].size());
    for (size_t i = 0; i < s.Cluster[v].size(); ++i)
    {
      EXPECT_EQ(s.Cluster[v][i].Point, before.Cluster[old][i].Point);
      const int hint = before.Cluster[old][i].Hint;
      if (hint >= 0 && before.T[hint].Alive)
        EXPECT_EQ(s.T[s.Cluster[v][i].Hint].V[0],
          std::lower_bound(liveVertices.begin(), liveVertices.end(), before.T[hint].V[0]) - liveVertices.begin());
      else
        EXPECT_EQ(s.Cluster[v][i].Hint, -1);
    }
    ASSERT_EQ(s.VT[v].size(), before.VT[old].size());
    for (int t : s.VT[v])
      EXPECT_TRUE(
        s.T[t].V[0] == static_cast<int>(v) || s.T[t].V[1] == static_cast<int>(v) || s.T[t].V[2] == static_cast<int>(v));
  }
  for (size_t t = 0; t < s.T.size(); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(liveVertices[s.T[t].V[k]], corners[t][k]);
  ExpectOrientedManifold(s);
  ExpectExactBins(*a);
  // The rest of a run on both: the same surface, live vertex for live vertex.
  for (Remesher* r : { a.get(), b.get() })
  {
    r->FlipPass();
    r->RelaxPass();
    double upper;
    long long inserted = 0;
    r->Enforce(upper, inserted);
  }
  std::vector<Vec3> pa, pb;
  for (size_t v = 0; v < a->Mesh.P.size(); ++v)
    if (a->Mesh.VAlive[v])
      pa.push_back(a->Mesh.P[v]);
  for (size_t v = 0; v < b->Mesh.P.size(); ++v)
    if (b->Mesh.VAlive[v])
      pb.push_back(b->Mesh.P[v]);
  EXPECT_EQ(pa, pb);
  EXPECT_EQ(LiveTriangles(a->Mesh), LiveTriangles(b->Mesh));
}

TEST(Remesher, RunMeetsTheBoundOnABumpyPatch)
{
  // A grid of 0.5 mm squares over a smooth bump 2 mm high: remeshed to 2 mm edges within 0.05 mm.
  const amSurfaceMesh m = BumpyPatch();
  auto r = std::make_unique<Remesher>();
  r->Setup(m, std::vector<Mat3>(m.Points.size(), Mat3::Identity() / 4.0), 0.05);
  std::vector<double> progress;
  const Remesher::Result result = r->Run(3, [&](double f) { progress.push_back(f); });
  std::printf("bump: %lld -> %lld triangles, Hausdorff %.4f (bound %.4f), %lld collapses, %lld flips, %lld moves\n",
    static_cast<long long>(m.Triangles.size()), LiveTriangles(r->Mesh), result.Hausdorff, result.UpperBound,
    r->Collapses(), r->Flips(), r->Moves());
  EXPECT_LE(result.Hausdorff, 0.05);
  EXPECT_GE(result.UpperBound, result.Hausdorff);
  EXPECT_LT(LiveTriangles(r->Mesh), static_cast<long long>(m.Triangles.size()) / 2);
  EXPECT_GT(r->Collapses(), 0);
  ExpectOrientedManifold(r->Mesh);
  ASSERT_FALSE(progress.empty());
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_LE(progress.back(), 1.0);
}

TEST(Remesher, HeldVerticesKeepTheInputTriangles)
{
  // The bumpy patch with the vertices of its left half held: every input triangle of three held
  // vertices is in the result as it was (the same corners, in the same places); the right half
  // is remeshed as without them.
  const amSurfaceMesh m = BumpyPatch();
  auto r = std::make_unique<Remesher>();
  r->Setup(m, std::vector<Mat3>(m.Points.size(), Mat3::Identity() / 4.0), 0.05);
  for (size_t v = 0; v < m.Points.size(); ++v)
    r->Mesh.Held[v] = m.Points[v][0] < 5.9;
  const Remesher::Result result = r->Run(3, {});
  EXPECT_LE(result.Hausdorff, 0.05);
  using Corner = std::array<double, 3>;
  std::set<std::array<Corner, 3>> out;
  long long right = 0;
  for (const Triangle& t : r->Mesh.T)
    if (t.Alive)
    {
      std::array<Corner, 3> c;
      for (int k = 0; k < 3; ++k)
        c[k] = { r->Mesh.P[t.V[k]][0], r->Mesh.P[t.V[k]][1], r->Mesh.P[t.V[k]][2] };
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      out.insert(c);
      right += c[0][0] > 6.1;
    }
  long long held = 0, kept = 0;
  for (const auto& tri : m.Triangles)
  {
    if (!(m.Points[tri[0]][0] < 5.9 && m.Points[tri[1]][0] < 5.9 && m.Points[tri[2]][0] < 5.9))
      continue;
    ++held;
    std::array<Corner, 3> c = { m.Points[tri[0]], m.Points[tri[1]], m.Points[tri[2]] };
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    kept += out.count(c);
  }
  EXPECT_GT(held, 400);
  EXPECT_EQ(kept, held);
  // The right half (x > 6.1 mm: 11 of the 24 columns, 528 input triangles) coarsened.
  EXPECT_LT(right, 200);
  ExpectOrientedManifold(r->Mesh);
}
