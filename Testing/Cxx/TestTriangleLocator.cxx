#include "amTriangleLocator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{
/// A bumpy height field z = 0.3 sin(x) cos(y) over [0, 10]^2, n x n quads split in two.
void Terrain(int n, std::vector<std::array<double, 3>>& points, std::vector<std::array<vtkIdType, 3>>& tris)
{
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
    {
      const double x = 10.0 * i / n, y = 10.0 * j / n;
      points.push_back({ x, y, 0.3 * std::sin(x) * std::cos(y) });
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      tris.push_back({ a, b, d });
      tris.push_back({ a, d, c });
    }
}

/// The terrain of n x n quads and its locator.
struct TerrainLocator
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<vtkIdType, 3>> tris;
  amTriangleLocator locator;
  explicit TerrainLocator(int n)
  {
    Terrain(n, this->points, this->tris);
    this->locator.Build(this->points, this->tris);
  }
};
}

// WithinDistance answers as ClosestPoint does, with or without a hint (a good one, a stale one,
// one out of range), and a hint it is given comes back as a triangle within reach.
TEST(TriangleLocator, WithinDistanceAgreesWithClosestPointWhateverTheHint)
{
  TerrainLocator terrain(40);
  const auto& points = terrain.points;
  const auto& tris = terrain.tris;
  const amTriangleLocator& locator = terrain.locator;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> xy(-0.5, 10.5), z(-0.6, 0.6), radius(0.0, 0.3);
  vtkIdType hint = -1;
  int agreedWithin = 0, hintsKept = 0;
  for (int q = 0; q < 4000; ++q)
  {
    const double x[3] = { xy(random), xy(random), z(random) };
    const double r = radius(random), r2 = r * r;
    double closest[3];
    vtkIdType t;
    const bool within = locator.ClosestPoint(x, closest, t) <= r2;
    ASSERT_EQ(within, locator.WithinDistance(x, r2));
    const vtkIdType before = hint;
    ASSERT_EQ(within, locator.WithinDistance(x, r2, nullptr, &hint)) << "query " << q << " hint " << before;
    if (within)
    {
      ++agreedWithin;
      ASSERT_GE(hint, 0);
      ASSERT_LT(hint, static_cast<vtkIdType>(tris.size()));
      double c2[3];
      const auto& tri = tris[hint];
      EXPECT_LE(amTriangleLocator::ClosestPointOnTriangle(
                  x, points[tri[0]].data(), points[tri[1]].data(), points[tri[2]].data(), c2),
        r2);
    }
    else
    {
      hintsKept += hint == before;
      EXPECT_EQ(hint, before); // nothing within reach: the hint stays
    }
    if (q % 97 == 0)
      hint = static_cast<vtkIdType>(tris.size()) + 5; // out of range: ignored
  }
  EXPECT_GT(agreedWithin, 500); // both answers occur
  EXPECT_GT(4000 - agreedWithin, 500);
  // With a normal: only the triangles facing that way count, hint or not.
  const double up[3] = { 0, 0, 1 }, down[3] = { 0, 0, -1 }, x[3] = { 5.0, 5.0, 1.0 };
  hint = -1;
  EXPECT_TRUE(locator.WithinDistance(x, 4.0, up, &hint));
  EXPECT_GE(hint, 0);
  EXPECT_FALSE(locator.WithinDistance(x, 4.0, down, &hint)); // every triangle faces up
}

// ClosestPoint finds the distance every triangle's closest point gives at least (the bins and
// the pruning by bounding spheres and planes skip no nearer triangle), exactly: the brute-force
// minimum, bit for bit, near the terrain and far from it.
TEST(TriangleLocator, ClosestPointIsTheBruteForceMinimum)
{
  const TerrainLocator terrain(30);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> xy(-3.0, 13.0), z(-4.0, 4.0);
  for (int q = 0; q < 1500; ++q)
  {
    const double x[3] = { xy(random), xy(random), q % 3 == 0 ? 0.01 * z(random) : z(random) };
    double best = std::numeric_limits<double>::infinity(), c[3], closest[3];
    for (const auto& tri : terrain.tris)
      best = std::min(best,
        amTriangleLocator::ClosestPointOnTriangle(
          x, terrain.points[tri[0]].data(), terrain.points[tri[1]].data(), terrain.points[tri[2]].data(), c));
    vtkIdType t;
    ASSERT_EQ(best, terrain.locator.ClosestPoint(x, closest, t)) << "query " << q;
    ASSERT_GE(t, 0);
    // Within a bound above the distance: the same answer; below it: none.
    ASSERT_EQ(best, terrain.locator.ClosestPointWithin(x, 1.0001 * best + 1e-12, closest, t));
    ASSERT_EQ(terrain.locator.ClosestPointWithin(x, 0.9999 * best, closest, t), 0.9999 * best);
    ASSERT_EQ(t, -1);
  }
}
