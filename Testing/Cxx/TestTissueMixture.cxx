// The tissue classes read from a scan's histogram: centres and boundaries on mixtures of known
// classes, classes a scan does not show, windowed scans, and what is not a CT.
#include "Anatomy/amTissueMixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace
{
struct Tissue
{
  double Mean, Sigma, Fraction;
};

// n samples drawn from the tissues, plus a uniform share between -900 and 0 (partial volume).
std::vector<float> Body(const std::vector<Tissue>& tissues, int n, unsigned seed = 3, double partial = 0.05)
{
  std::mt19937 random(seed);
  std::vector<float> v;
  for (const auto& t : tissues)
  {
    std::normal_distribution<double> g(t.Mean, t.Sigma);
    for (int i = 0; i < static_cast<int>(t.Fraction * n); ++i)
      v.push_back(static_cast<float>(g(random)));
  }
  std::uniform_real_distribution<double> u(-900.0, 0.0);
  for (int i = 0; i < static_cast<int>(partial * n); ++i)
    v.push_back(static_cast<float>(u(random)));
  return v;
}

using M = amTissueMixture;
}

TEST(TissueMixture, FindsEveryClassOfAnArterialPhaseChest)
{
  const auto v =
    Body({ { -850, 40, 0.25 }, { -100, 20, 0.15 }, { 40, 20, 0.45 }, { 300, 25, 0.05 }, { 800, 150, 0.04 } }, 200000);
  const M::Result r = M::Fit(v.data(), nullptr, v.size());
  ASSERT_TRUE(r.Problem.empty()) << r.Problem;
  const double expected[] = { 0, -850, -100, 40, 300, 800 };
  for (int c = M::Lung; c <= M::Bone; ++c)
  {
    EXPECT_TRUE(r.Classes[c].Found) << M::Name(c);
    EXPECT_NEAR(r.Classes[c].Mean, expected[c], c == M::Bone ? 30.0 : 5.0) << M::Name(c);
  }
  EXPECT_NEAR(r.Classes[M::Soft].Sigma, 20.0, 3.0);
  EXPECT_NEAR(r.Classes[M::Soft].Weight, 0.45 / 1.04, 0.03);
  // Half-way boundaries, and the soft|blood one 2.5 spreads below the blood.
  EXPECT_NEAR(r.Upper[M::Lung], -475, 10);
  EXPECT_NEAR(r.Upper[M::Fat], -30, 5);
  EXPECT_NEAR(r.Upper[M::Soft], 300 - 2.5 * 25, 12);
  EXPECT_GT(r.Upper[M::Blood], 370);
  EXPECT_LT(r.Upper[M::Blood], 500);
  EXPECT_EQ(M::Classify(r, -1000), M::Air);
  EXPECT_EQ(M::Classify(r, 45), M::Soft);
  EXPECT_EQ(M::Classify(r, 1200), M::Bone);
}

TEST(TissueMixture, ALatePhaseKeepsTheEnhancedWallSoft)
{
  // Blood at 170 HU, an enhanced myocardium at 95 beside 40 HU muscle, 35 HU of noise: blood and
  // wall are one slope of the histogram, and the wall stays soft tissue.
  const auto v = Body({ { -850, 50, 0.25 }, { -100, 35, 0.15 }, { 40, 35, 0.40 }, { 95, 35, 0.04 }, { 170, 35, 0.05 },
                        { 800, 150, 0.04 } },
    200000);
  const M::Result r = M::Fit(v.data(), nullptr, v.size());
  ASSERT_TRUE(r.Problem.empty()) << r.Problem;
  EXPECT_EQ(M::Classify(r, 95), M::Soft);
  EXPECT_EQ(M::Classify(r, -850), M::Lung);
  EXPECT_EQ(M::Classify(r, -100), M::Fat);
  EXPECT_EQ(M::Classify(r, 800), M::Bone);
  // Without the wall, the same blood is a class of its own above it.
  const auto w =
    Body({ { -850, 50, 0.25 }, { -100, 35, 0.15 }, { 40, 35, 0.44 }, { 170, 25, 0.05 }, { 800, 150, 0.04 } }, 200000);
  const M::Result q = M::Fit(w.data(), nullptr, w.size());
  EXPECT_TRUE(q.Classes[M::Blood].Found);
  EXPECT_NEAR(q.Classes[M::Blood].Mean, 170, 20);
  EXPECT_GT(q.Upper[M::Soft], 95);
  EXPECT_LT(q.Upper[M::Soft], 170);
}

TEST(TissueMixture, AScanWithoutContrastHasNoBloodClassAndOneWithoutBoneNoBone)
{
  const auto v = Body({ { -850, 40, 0.3 }, { -100, 20, 0.2 }, { 40, 20, 0.5 } }, 100000);
  const M::Result r = M::Fit(v.data(), nullptr, v.size());
  ASSERT_TRUE(r.Problem.empty()) << r.Problem;
  EXPECT_FALSE(r.Classes[M::Blood].Found);
  EXPECT_FALSE(r.Classes[M::Bone].Found);
  EXPECT_TRUE(r.Classes[M::Soft].Found);
  EXPECT_EQ(M::Classify(r, 250), M::Bone); // no empty class (blood) takes a value
  // Bone without a peak of its own (trabecular bone at coarse voxels, or cropped away), in a scan
  // without contrast, is what lies 3 spreads above soft tissue.
  EXPECT_EQ(M::Classify(r, 90), M::Soft);
  EXPECT_EQ(M::Classify(r, 110), M::Bone);
}

TEST(TissueMixture, AWindowedScanClipsLungFatAndAirToOneClass)
{
  // Window 600/300 (floor 0 HU): lung, fat and air all read as the floor (-1000 after the
  // torso segmentation's conversion), cortical bone as the ceiling (+1000).
  std::vector<float> v =
    Body({ { -1000, 0.01, 0.40 }, { 40, 15, 0.5 }, { 260, 20, 0.05 }, { 1000, 0.01, 0.05 } }, 100000, 5, 0.0);
  const M::Result r = M::Fit(v.data(), nullptr, v.size());
  ASSERT_TRUE(r.Problem.empty()) << r.Problem;
  EXPECT_TRUE(r.Classes[M::Air].Found);
  EXPECT_FALSE(r.Classes[M::Lung].Found);
  EXPECT_FALSE(r.Classes[M::Fat].Found);
  EXPECT_TRUE(r.Classes[M::Bone].Found);
  EXPECT_EQ(M::Classify(r, -1000), M::Air);
  EXPECT_EQ(M::Classify(r, 40), M::Soft);
  EXPECT_EQ(M::Classify(r, 1000), M::Bone);
}

TEST(TissueMixture, WhatIsNotACTInHUSaysSo)
{
  // Stored unsigned without the rescale: every tissue 1024 too high.
  const auto v = Body({ { 174, 40, 0.3 }, { 924, 20, 0.2 }, { 1064, 20, 0.5 } }, 50000, 3, 0.0);
  const M::Result r = M::Fit(v.data(), nullptr, v.size());
  EXPECT_NE(r.Problem.find("no soft tissue"), std::string::npos) << r.Problem;
  const M::Result empty = M::Fit(v.data(), std::vector<unsigned char>(v.size(), 0).data(), v.size());
  EXPECT_NE(empty.Problem.find("no body"), std::string::npos);
}

TEST(TissueMixture, IsTheSameForTheSameValuesInAnyOrder)
{
  auto v = Body({ { -850, 40, 0.3 }, { -100, 20, 0.2 }, { 40, 20, 0.5 } }, 50000);
  const M::Result a = M::Fit(v.data(), nullptr, v.size());
  std::reverse(v.begin(), v.end());
  const M::Result b = M::Fit(v.data(), nullptr, v.size());
  for (int c = 0; c < M::NumberOfClasses; ++c)
  {
    EXPECT_EQ(a.Classes[c].Mean, b.Classes[c].Mean);
    EXPECT_EQ(a.Upper[c], b.Upper[c]);
  }
}
