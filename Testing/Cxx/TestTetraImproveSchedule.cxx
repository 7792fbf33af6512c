// The sliver phase's schedule (amTetraImproveSchedule.h) on hand-made deviations.
#include "amTetraImproveSchedule.h"

#include <gtest/gtest.h>

using amTetraImprove::First;
using amTetraImprove::SliverSchedule;

TEST(TetraImproveSchedule, BudgetsShrinkPastTheBoundBisectThenStartAgainPerOrder)
{
  SliverSchedule schedule(1.0);
  EXPECT_EQ(schedule.Attempts(), 12);
  EXPECT_EQ(schedule.Order(0), First::Slide);
  EXPECT_EQ(schedule.Order(3), First::Slide);
  EXPECT_EQ(schedule.Order(4), First::Relabel);
  EXPECT_EQ(schedule.Order(11), First::Collapse);
  EXPECT_DOUBLE_EQ(schedule.Budget(), 1.0); // the whole bound first
  schedule.Record(0, 1.2);                  // past the bound: a little under what would have fitted
  EXPECT_DOUBLE_EQ(schedule.Budget(), 0.9 / 1.2);
  schedule.Record(1, 0.8); // within: half-way between it and the budget that went past
  EXPECT_DOUBLE_EQ(schedule.Budget(), 0.5 * (0.75 + 1.0));
  schedule.Record(2, 0.95);
  EXPECT_DOUBLE_EQ(schedule.Budget(), 0.5 * (0.875 + 1.0));
  schedule.Record(3, 1.5); // the order's last: the next order starts from the whole bound
  EXPECT_DOUBLE_EQ(schedule.Budget(), 1.0);
  schedule.Record(4, 0.5); // within with nothing past: grows towards the bound, at most doubling
  EXPECT_DOUBLE_EQ(schedule.Budget(), 1.96);
  schedule.Record(5, 0.99);
  EXPECT_DOUBLE_EQ(schedule.Budget(), 1.96 * 0.98 / 0.99);
  schedule.Record(6, 0.1);
  EXPECT_DOUBLE_EQ(schedule.Budget(), 2 * 1.96); // at most twice the largest within
}
