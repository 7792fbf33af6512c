// The Euclidean distance transform and its bounded forms (amVoxelDistance.cxx).
#include "Torso/amVoxelGrid.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>

namespace
{
amVoxelGrid Grid(int nx, int ny, int nz, double sx, double sy, double sz)
{
  amVoxelGrid g;
  g.N[0] = nx, g.N[1] = ny, g.N[2] = nz;
  g.Spacing[0] = sx, g.Spacing[1] = sy, g.Spacing[2] = sz;
  return g;
}

// A blob of random voxels inside the box [lo, hi) of the grid.
amVoxelMask Blob(const amVoxelGrid& g, const int lo[3], const int hi[3], int oneIn, unsigned seed)
{
  std::mt19937 random(seed);
  amVoxelMask mask(g.Size(), 0);
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i)
        mask[g.Index(i, j, k)] = random() % oneIn != 0;
  return mask;
}
}

TEST(VoxelGrid, DistanceIsExactOnAnAnisotropicGrid)
{
  amVoxelGrid g;
  g.N[0] = 9, g.N[1] = 7, g.N[2] = 5;
  g.Spacing[0] = 0.7, g.Spacing[1] = 1.3, g.Spacing[2] = 2.5;
  std::mt19937 random(3);
  amVoxelMask mask(g.Size(), 0);
  for (auto& m : mask)
    m = random() % 17 == 0;
  const std::vector<float> d = amVoxel::Distance(g, mask);
  for (std::size_t v = 0; v < g.Size(); ++v)
  {
    int a[3], b[3];
    g.Ijk(v, a);
    double best = std::numeric_limits<double>::max();
    for (std::size_t w = 0; w < g.Size(); ++w)
      if (mask[w])
      {
        g.Ijk(w, b);
        double s = 0;
        for (int c = 0; c < 3; ++c)
          s += std::pow((a[c] - b[c]) * g.Spacing[c], 2);
        best = std::min(best, std::sqrt(s));
      }
    ASSERT_NEAR(d[v], best, 1e-4) << "voxel " << v;
  }
}

TEST(VoxelGrid, DistanceAcrossTilesIsTheSameAlongEveryAxis)
{
  // Lines across the first axis go in tiles: a grid whose first size is no multiple of a tile,
  // turned so that each axis in turn is the first, gives the same distances.
  const int n[3] = { 37, 21, 13 };
  const amVoxelGrid g = Grid(n[0], n[1], n[2], 1.0, 1.0, 1.0);
  std::mt19937 random(5);
  amVoxelMask mask(g.Size());
  for (auto& m : mask)
    m = random() % 29 == 0;
  const std::vector<float> d = amVoxel::Distance(g, mask);
  const amVoxelGrid t = Grid(n[2], n[0], n[1], 1.0, 1.0, 1.0); // (i, j, k) -> (k, i, j)
  amVoxelMask turned(g.Size());
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        turned[t.Index(k, i, j)] = mask[g.Index(i, j, k)];
  const std::vector<float> e = amVoxel::Distance(t, turned);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        ASSERT_EQ(d[g.Index(i, j, k)], e[t.Index(k, i, j)]) << i << " " << j << " " << k;
}

TEST(VoxelGrid, DepthIsTheDistanceToTheOutsideOverTheRegionsBox)
{
  const amVoxelGrid g = Grid(40, 30, 20, 0.7, 1.3, 2.5);
  const int lo[3] = { 9, 4, 3 }, hi[3] = { 31, 26, 17 };
  amVoxelMask region = Blob(g, lo, hi, 9, 7);
  region[g.Index(0, 29, 19)] = 1; // a voxel at the grid's corner: the box is the whole grid
  for (const bool corner : { false, true })
  {
    if (!corner)
      region[g.Index(0, 29, 19)] = 0;
    amVoxelMask outside(g.Size());
    for (std::size_t v = 0; v < g.Size(); ++v)
      outside[v] = !region[v];
    const std::vector<float> full = amVoxel::Distance(g, outside), depth = amVoxel::Depth(g, region);
    std::size_t deep = 0;
    for (std::size_t v = 0; v < g.Size(); ++v)
    {
      ASSERT_EQ(depth[v], full[v]) << "voxel " << v << (corner ? " (corner)" : "");
      deep += depth[v] > 2.0;
    }
    EXPECT_GT(deep, 50u); // the blob has an inside to measure
  }
  EXPECT_EQ(amVoxel::Depth(g, amVoxelMask(g.Size(), 0)), std::vector<float>(g.Size(), 0.0f));
}

TEST(VoxelGrid, DistanceWithinIsExactUpToItsReach)
{
  const amVoxelGrid g = Grid(50, 40, 30, 0.8, 0.8, 2.0);
  const int lo[3] = { 20, 15, 12 }, hi[3] = { 28, 22, 16 };
  const amVoxelMask mask = Blob(g, lo, hi, 3, 11);
  const std::vector<float> full = amVoxel::Distance(g, mask);
  for (const double reach : { 0.5, 3.0, 7.5 })
  {
    const std::vector<float> near = amVoxel::DistanceWithin(g, mask, reach);
    std::size_t within = 0, beyond = 0;
    for (std::size_t v = 0; v < g.Size(); ++v)
      if (full[v] <= reach)
      {
        ASSERT_EQ(near[v], full[v]) << "voxel " << v << ", reach " << reach;
        ++within;
      }
      else
      {
        ASSERT_GT(near[v], reach) << "voxel " << v << ", reach " << reach;
        beyond += near[v] == std::numeric_limits<float>::max();
      }
    EXPECT_GT(within, 0u);
    EXPECT_GT(beyond, 0u); // the box is smaller than the grid
  }
  const std::vector<float> none = amVoxel::DistanceWithin(g, amVoxelMask(g.Size(), 0), 5.0);
  EXPECT_EQ(*std::min_element(none.begin(), none.end()), std::numeric_limits<float>::max());
}
