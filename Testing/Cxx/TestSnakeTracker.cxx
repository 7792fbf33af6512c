// The snake's per-organ tracker without a pipeline: a bright ball in a dark region of interest,
// found in 3-D, slice by slice and with polar contours, its seeds given in the scan's indices.
#include "amSnakeTracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace
{
/// A 40^3 region of 1 mm voxels starting at voxel (5, 6, 7) of the scan: a ball of radius 10 mm
/// at 200 around the region's centre, 0 elsewhere.
struct Ball
{
  const int Lo[3] = { 5, 6, 7 }, Size[3] = { 40, 40, 40 };
  const double Spacing[3] = { 1, 1, 1 }, Radius = 10;
  std::vector<float> Values;
  std::array<double, 3> Centre; // in the scan's indices
  Ball()
  {
    for (int a = 0; a < 3; ++a)
      this->Centre[a] = this->Lo[a] + 19.5;
    for (int k = 0; k < 40; ++k)
      for (int j = 0; j < 40; ++j)
        for (int i = 0; i < 40; ++i)
        {
          const double x = i - 19.5, y = j - 19.5, z = k - 19.5;
          this->Values.push_back(x * x + y * y + z * z <= this->Radius * this->Radius ? 200.0f : 0.0f);
        }
  }
  double Volume() const { return 4.0 / 3.0 * M_PI * this->Radius * this->Radius * this->Radius; }
};

size_t Count(const std::vector<unsigned char>& m)
{
  size_t n = 0;
  for (unsigned char c : m)
    n += c;
  return n;
}
}

TEST(SnakeTracker, FindsABallInEveryMode)
{
  const Ball ball;
  struct Case
  {
    const char* Name;
    int Mode, ContourModel;
  };
  for (const Case& c :
    { Case{ "3-D level set", amSnakeTracker::Parameters::ThreeD, amSnakeTracker::Parameters::LevelSet },
      Case{ "slice by slice", amSnakeTracker::Parameters::SliceBySlice, amSnakeTracker::Parameters::LevelSet },
      Case{ "polar", amSnakeTracker::Parameters::SliceBySlice, amSnakeTracker::Parameters::Polar } })
  {
    amSnakeTracker::Parameters p;
    p.Mode = c.Mode;
    p.ContourModel = c.ContourModel;
    p.OutsideThreshold = 100; // the polar contours' edge: half-way between ball and background
    amSnakeTracker tracker(p, ball.Spacing);
    tracker.SetRegion(ball.Lo, ball.Size, ball.Values);
    tracker.MeasureSeeds({ ball.Centre });
    EXPECT_NEAR(tracker.SeedMean(0), 200.0, 1.0) << c.Name; // the seed ball lies inside, smoothing aside
    std::vector<double> progress;
    ASSERT_TRUE(tracker.Segment(
      200.0, [&](double f) { progress.push_back(f); }, nullptr))
      << c.Name << tracker.Error;
    const double volume = static_cast<double>(Count(tracker.Inside()));
    std::printf("%s: %.0f voxels for a ball of %.0f mm^3, interval [%.0f, %.0f]\n", c.Name, volume, ball.Volume(),
      tracker.Lower(), tracker.Upper());
    EXPECT_NEAR(volume / ball.Volume(), 1.0, 0.12) << c.Name;
    EXPECT_EQ(tracker.Inside()[(20 * 40 + 20) * 40 + 20], 1) << c.Name;
    EXPECT_EQ(tracker.Inside()[0], 0) << c.Name;
    ASSERT_FALSE(progress.empty()) << c.Name;
    EXPECT_LE(progress.back(), 1.0) << c.Name;
  }
}

TEST(SnakeTracker, IntervalFromTheSeedsOrGiven)
{
  const Ball ball;
  amSnakeTracker::Parameters p;
  p.RefineToHalfContrast = false;
  amSnakeTracker automatic(p, ball.Spacing);
  automatic.SetRegion(ball.Lo, ball.Size, ball.Values);
  automatic.MeasureSeeds({ ball.Centre });
  ASSERT_TRUE(automatic.Segment(200.0, nullptr, nullptr));
  // A uniform ball: no spread, so the window's minimum width around the mean.
  EXPECT_NEAR(automatic.Lower(), 200.0 - p.MinimumIntensityWindow, 1.0);
  EXPECT_NEAR(automatic.Upper(), 200.0 + p.MinimumIntensityWindow, 1.0);
  p.AutomaticThresholds = false;
  p.LowerThreshold = 300; // above the ball: the contour vanishes
  p.UpperThreshold = 400;
  amSnakeTracker given(p, ball.Spacing);
  given.SetRegion(ball.Lo, ball.Size, ball.Values);
  given.MeasureSeeds({ ball.Centre });
  ASSERT_TRUE(given.Segment(200.0, nullptr, nullptr));
  EXPECT_EQ(given.Lower(), 300);
  EXPECT_EQ(Count(given.Inside()), 0u);
}

TEST(SnakeTracker, AbortStopsSliceBySlice)
{
  const Ball ball;
  amSnakeTracker::Parameters p;
  p.Mode = amSnakeTracker::Parameters::SliceBySlice;
  amSnakeTracker tracker(p, ball.Spacing);
  tracker.SetRegion(ball.Lo, ball.Size, ball.Values);
  tracker.MeasureSeeds({ ball.Centre });
  EXPECT_FALSE(tracker.Segment(200.0, nullptr, []() { return true; }));
  EXPECT_TRUE(tracker.Error.empty()); // aborted, not failed
}

// On a noisy ball the front settles into a cycle of two states whose RMS change stays above
// MaximumRMSError: ITK's stop alone runs every iteration; the stall stop ends the evolution once
// the inside keeps its size, with the same inside.
TEST(SnakeTracker, StopsWhenTheInsideNoLongerChanges)
{
  Ball ball;
  std::mt19937 random(7);
  std::normal_distribution<float> noise(0.0f, 30.0f);
  for (float& v : ball.Values)
    v += noise(random);
  auto segment = [&](bool stall, amSnakeTracker& tracker) {
    tracker.SetRegion(ball.Lo, ball.Size, ball.Values);
    tracker.MeasureSeeds({ ball.Centre });
    EXPECT_TRUE(tracker.Segment(300.0, nullptr, nullptr)) << stall << tracker.Error;
  };
  amSnakeTracker::Parameters p;
  p.NumberOfIterations = 400;
  p.StopOnStall = false;
  amSnakeTracker full(p, ball.Spacing);
  segment(false, full);
  p.StopOnStall = true;
  amSnakeTracker stopped(p, ball.Spacing);
  segment(true, stopped);
  std::printf("iterations: %lld with ITK's stop alone, %lld with the stall stop; %zu voxels inside\n",
    full.Iterations(), stopped.Iterations(), Count(stopped.Inside()));
  // The ball's first evolution runs to the limit without the stall stop (the refinement's, at
  // most 200, too), and stops early with it.
  EXPECT_GE(full.Iterations(), p.NumberOfIterations);
  EXPECT_LT(stopped.Iterations(), full.Iterations() / 2);
  EXPECT_EQ(stopped.Inside(), full.Inside());
  EXPECT_NEAR(static_cast<double>(Count(stopped.Inside())) / ball.Volume(), 1.0, 0.15);
}

// The first evolution at twice the voxel size: the same organ as at full resolution alone, a rod
// five voxels across (two and a half on the coarse grid) to its far end included.
TEST(SnakeTracker, CoarseToFineFindsTheSameOrgan)
{
  Ball ball;
  // A rod of radius 2.5 mm along x from the ball's surface to the region's edge.
  for (int k = 0; k < 40; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 20; i < 40; ++i)
      {
        const double y = j - 19.5, z = k - 19.5;
        if (y * y + z * z <= 2.5 * 2.5)
          ball.Values[(k * 40 + j) * 40 + i] = 200.0f;
      }
  std::mt19937 random(3);
  std::normal_distribution<float> noise(0.0f, 20.0f);
  for (float& v : ball.Values)
    v += noise(random);
  auto segment = [&](bool coarse) {
    amSnakeTracker::Parameters p;
    p.CoarseToFine = coarse;
    amSnakeTracker tracker(p, ball.Spacing);
    tracker.SetRegion(ball.Lo, ball.Size, ball.Values);
    tracker.MeasureSeeds({ ball.Centre });
    EXPECT_TRUE(tracker.Segment(300.0, nullptr, nullptr)) << coarse << tracker.Error;
    return tracker.Inside();
  };
  const std::vector<unsigned char> fine = segment(false), coarse = segment(true);
  size_t differ = 0, rod = 0;
  for (size_t i = 0; i < fine.size(); ++i)
    differ += fine[i] != coarse[i];
  for (int i = 32; i < 38; ++i) // the rod's far end, beyond the ball's reach
    rod += coarse[(20 * 40 + 20) * 40 + i];
  std::printf("%zu voxels inside at full resolution, %zu from the coarse grid, %zu differ, rod end %zu\n", Count(fine),
    Count(coarse), differ, rod);
  EXPECT_NEAR(static_cast<double>(Count(coarse)) / ball.Volume(), 1.0, 0.15);
  EXPECT_LT(differ, Count(fine) / 50);
  EXPECT_EQ(rod, 6u);
}

// The full resolution evolved in a box around its initial contour: the same organ voxel for voxel
// as on the whole region. A ball in a region much larger than itself: the box is kept. The same
// ball with a rod too thin for the coarse grid along x to the region's far side: the front
// leaves the coarse contour's box along the rod, and the whole region is evolved instead.
TEST(SnakeTracker, EvolvesInABoxAsOnTheWholeRegion)
{
  const int lo[3] = { 3, 2, 1 }, size[3] = { 96, 64, 64 };
  const double spacing[3] = { 1, 1, 1 };
  for (const double rodRadius : { 0.0, 2.0 })
  {
    // A ball of radius 10 mm at (30, 32, 32), noisy.
    std::vector<float> values(static_cast<size_t>(size[0]) * size[1] * size[2]);
    std::mt19937 random(5);
    std::normal_distribution<float> noise(0.0f, 20.0f);
    for (int k = 0; k < size[2]; ++k)
      for (int j = 0; j < size[1]; ++j)
        for (int i = 0; i < size[0]; ++i)
        {
          const double x = i - 30, y = j - 32, z = k - 32;
          const bool inside = x * x + y * y + z * z <= 100 || (x > 0 && y * y + z * z <= rodRadius * rodRadius);
          values[(static_cast<size_t>(k) * size[1] + j) * size[0] + i] = (inside ? 200.0f : 0.0f) + noise(random);
        }
    auto segment = [&](int margin, int& boxed) {
      amSnakeTracker::Parameters p;
      p.BoxMargin = margin;
      amSnakeTracker tracker(p, spacing);
      tracker.SetRegion(lo, size, values);
      tracker.MeasureSeeds({ { lo[0] + 30.0, lo[1] + 32.0, lo[2] + 32.0 } });
      EXPECT_TRUE(tracker.Segment(300.0, nullptr, nullptr)) << margin << tracker.Error;
      boxed = tracker.BoxEvolutions();
      return tracker.Inside();
    };
    // Margin 0: the whole region; 12: the default; 7: a box one voxel wider than the guard.
    int wholeBoxed, boxBoxed, tightBoxed;
    const std::vector<unsigned char> whole = segment(0, wholeBoxed), box = segment(12, boxBoxed),
                                     tight = segment(7, tightBoxed);
    size_t rod = 0;
    for (int i = 88; i < 94; ++i) // the rod's far end
      rod += box[(32 * 64 + 32) * 96 + i];
    std::printf("rod radius %.0f: %zu voxels inside; evolutions in a box: %d (margin 12), %d (margin 7); rod end %zu\n",
      rodRadius, Count(whole), boxBoxed, tightBoxed, rod);
    EXPECT_EQ(wholeBoxed, 0);
    EXPECT_EQ(box, whole) << rodRadius;
    EXPECT_EQ(tight, whole) << rodRadius;
    if (rodRadius == 0)
    {
      EXPECT_GE(boxBoxed, 1);
      EXPECT_NEAR(static_cast<double>(Count(box)) / (4.0 / 3.0 * M_PI * 1000.0), 1.0, 0.12);
    }
    else
    {
      EXPECT_EQ(boxBoxed, 0);
      EXPECT_EQ(rod, 6u);
    }
  }
}
