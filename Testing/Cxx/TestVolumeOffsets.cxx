// amVolumeOffsets: the offsets of smallest weighted norm that give every region its volume back,
// checked against hand-solved cases (one region, two nested regions, the clamp).
#include "amVolumeOffsets.h"

#include <gtest/gtest.h>

TEST(VolumeOffsets, OneRegionGrowsByErrorOverSensitivity)
{
  // Region 1 inside the outside (label 0): the sheet's normal points out of 0 into 1, so region
  // 1 grows when the sheet moves against it: o = -error / sensitivity.
  const std::vector<amVolumeOffsets::Sheet> sheets = { { 0, 1, 20.0, 25.0 } };
  const std::vector<double> o = amVolumeOffsets::Solve(sheets, { { 1, 5.0 } }, 10.0);
  ASSERT_EQ(o.size(), 1u);
  EXPECT_NEAR(o[0], -5.0 / 20.0, 1e-6);
}

TEST(VolumeOffsets, NestedRegionsEachGetTheirError)
{
  // 2 inside 1 inside the outside 0. Sheet (0,1): region 1's outer boundary; sheet (1,2): the
  // interface, its normal out of 1 into 2. Region 1 must gain 3, region 2 lose 2: the interface
  // moves by +2/s12 (region 1 gains 2 there, region 2 loses 2), the outer sheet gives region 1
  // the remaining 1: -1/s01.
  const double s01 = 40, s12 = 10;
  const std::vector<amVolumeOffsets::Sheet> sheets = { { 0, 1, s01, 40 }, { 1, 2, s12, 10 } };
  const std::vector<double> o = amVolumeOffsets::Solve(sheets, { { 1, 3.0 }, { 2, -2.0 } }, 10.0);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_NEAR(o[0], -1.0 / s01, 1e-6);
  EXPECT_NEAR(o[1], 2.0 / s12, 1e-6);
}

TEST(VolumeOffsets, ClampedAndInvalidSheetsStay)
{
  const std::vector<amVolumeOffsets::Sheet> sheets = { { 0, 1, 1.0, 1.0 }, { 1, 1, 1.0, 1.0 }, { 0, 2, 0.0, 1.0 } };
  const std::vector<double> o = amVolumeOffsets::Solve(sheets, { { 1, -100.0 } }, 0.5);
  ASSERT_EQ(o.size(), 3u);
  EXPECT_DOUBLE_EQ(o[0], 0.5); // region 1 shrinks: the sheet moves into it, by at most 0.5
  EXPECT_EQ(o[1], 0.0);        // both sides one label
  EXPECT_EQ(o[2], 0.0);        // no sensitivity
  EXPECT_TRUE(amVolumeOffsets::Solve(sheets, {}, 1.0).empty());
}
