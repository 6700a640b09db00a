#include "tools/viz/chart_ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace topay::viz {
namespace {

TEST(ChartTicksTest, NiceTickStepIsTheSmallestRoundStepGivingAtMostTheTargetCount) {
  EXPECT_DOUBLE_EQ(NiceTickStep(10.0, 10), 1.0);
  EXPECT_DOUBLE_EQ(NiceTickStep(10.0, 4), 5.0);   // 2.5 -> 5
  EXPECT_DOUBLE_EQ(NiceTickStep(2.1, 4), 1.0);    // 0.525 -> 1
  EXPECT_DOUBLE_EQ(NiceTickStep(1.9, 4), 0.5);    // 0.475 -> 0.5
  EXPECT_DOUBLE_EQ(NiceTickStep(27.3, 10), 5.0);  // 2.73 -> 5
  EXPECT_DOUBLE_EQ(NiceTickStep(0.03, 3), 0.01);
  EXPECT_DOUBLE_EQ(NiceTickStep(0.031, 3), 0.02);
  EXPECT_DOUBLE_EQ(NiceTickStep(900.0, 10), 100.0);
  for (double span : {0.0123, 0.7, 3.3, 47.0, 1234.5}) {
    for (int target : {1, 3, 4, 7, 10}) {
      const double step = NiceTickStep(span, target);
      EXPECT_GE(step * target, span * (1.0 - 1e-12)) << span << " " << target;
      EXPECT_LT(step * target, 2.5 * span + 1e-12) << span << " " << target;
    }
  }
}

TEST(ChartTicksTest, NiceTickStepRejectsBadInput) {
  EXPECT_THROW(NiceTickStep(0.0, 4), std::invalid_argument);
  EXPECT_THROW(NiceTickStep(-1.0, 4), std::invalid_argument);
  EXPECT_THROW(NiceTickStep(std::nan(""), 4), std::invalid_argument);
  EXPECT_THROW(NiceTickStep(1.0, 0), std::invalid_argument);
}

TEST(ChartTicksTest, TicksAreTheMultiplesOfTheStepInTheRange) {
  EXPECT_EQ(TicksIn(-1.06, 1.06, 0.5), (std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0}));
  EXPECT_EQ(TicksIn(0.0, 27.3, 5.0), (std::vector<double>{0, 5, 10, 15, 20, 25}));
  // Ends within round-off of a multiple count.
  const std::vector<double> ticks = TicksIn(0.1 + 0.2, 0.9, 0.3);
  ASSERT_EQ(ticks.size(), 3u);
  EXPECT_NEAR(ticks.front(), 0.3, 1e-15);
  // Zero is exactly zero, never -0 or 1e-17.
  const std::vector<double> around_zero = TicksIn(-0.3, 0.3, 0.1);
  ASSERT_EQ(around_zero.size(), 7u);
  EXPECT_EQ(around_zero[3], 0.0);
  EXPECT_FALSE(std::signbit(around_zero[3]));
  EXPECT_TRUE(TicksIn(0.1, 0.2, 1.0).empty());
}

TEST(ChartTicksTest, TicksInRejectsBadInput) {
  EXPECT_THROW(TicksIn(1.0, 0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(TicksIn(0.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(TicksIn(0.0, std::numeric_limits<double>::infinity(), 1.0), std::invalid_argument);
  EXPECT_THROW(TicksIn(0.0, 1e6, 1.0), std::invalid_argument);  // a million ticks
}

TEST(ChartTicksTest, LabelsShowTheDigitsTheStepNeeds) {
  EXPECT_EQ(FormatTick(4.0, 2.0), "4");
  EXPECT_EQ(FormatTick(25.0, 5.0), "25");
  EXPECT_EQ(FormatTick(-0.5, 0.5), "-0.5");
  EXPECT_EQ(FormatTick(1.25, 0.25), "1.25");
  EXPECT_EQ(FormatTick(0.003, 0.001), "0.003");
  EXPECT_EQ(FormatTick(1.0, 0.1), "1.0");
  EXPECT_EQ(FormatTick(300.0, 100.0), "300");
  EXPECT_EQ(FormatTick(-0.0, 0.5), "0");
  EXPECT_EQ(FormatTick(-1e-17, 0.1), "0");
}

TEST(ChartTicksTest, PaddedRangeWidensConstantsAndPadsBothEnds) {
  auto [lo, hi] = PaddedRange(-1.0, 1.0, 0.05);
  EXPECT_DOUBLE_EQ(lo, -1.1);
  EXPECT_DOUBLE_EQ(hi, 1.1);
  std::tie(lo, hi) = PaddedRange(2.0, 2.0, 0.0);
  EXPECT_DOUBLE_EQ(lo, 1.8);
  EXPECT_DOUBLE_EQ(hi, 2.2);
  std::tie(lo, hi) = PaddedRange(0.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(lo, -1e-3);
  EXPECT_DOUBLE_EQ(hi, 1e-3);
  EXPECT_THROW(PaddedRange(1.0, 0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(PaddedRange(std::nan(""), 0.0, 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
