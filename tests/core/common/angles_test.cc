#include "core/common/angles.h"

#include <numbers>

#include <gtest/gtest.h>

namespace topay {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(WrapAngleTest, MapsIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(WrapAngle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(WrapAngle(kPi), kPi);
  EXPECT_DOUBLE_EQ(WrapAngle(-kPi), kPi);
  EXPECT_NEAR(WrapAngle(3.0 * kPi / 2.0), -kPi / 2.0, 1e-12);
  EXPECT_NEAR(WrapAngle(-5.0 * kPi / 2.0), -kPi / 2.0, 1e-12);
  EXPECT_NEAR(WrapAngle(100.0), 100.0 - 32.0 * kPi, 1e-12);
}

TEST(WrapAngleTest, KeepsEquivalentAngle) {
  for (double a = -20.0; a < 20.0; a += 0.37) {
    const double w = WrapAngle(a);
    EXPECT_GT(w, -kPi);
    EXPECT_LE(w, kPi);
    EXPECT_NEAR(std::sin(w), std::sin(a), 1e-12);
    EXPECT_NEAR(std::cos(w), std::cos(a), 1e-12);
  }
}

}  // namespace
}  // namespace topay
