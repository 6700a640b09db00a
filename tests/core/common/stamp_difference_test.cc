#include "core/common/stamp_difference.h"

#include <gtest/gtest.h>

#include <limits>

namespace topay {
namespace {

constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();

TEST(StampDifference, IsTheDifferenceWhenItFits) {
  EXPECT_EQ(StampDifferenceUs(1'700'000'000'000'100, 1'700'000'000'000'000), 100);
  EXPECT_EQ(StampDifferenceUs(-5, 7), -12);
  EXPECT_EQ(StampDifferenceUs(kMax, 0), kMax);
}

// The estimator_inputs fuzz target's input: a stamp near INT64_MIN against the clock.
TEST(StampDifference, SaturatesInsteadOfOverflowing) {
  EXPECT_EQ(StampDifferenceUs(-9'221'682'087'061'764'363, 1'700'000'000'000'000), kMin);
  EXPECT_EQ(StampDifferenceUs(1'700'000'000'000'000, -9'221'682'087'061'764'363), kMax);
  EXPECT_EQ(StampDifferenceUs(kMax, kMin), kMax);
  EXPECT_EQ(StampDifferenceUs(kMin, kMax), kMin);
}

}  // namespace
}  // namespace topay
