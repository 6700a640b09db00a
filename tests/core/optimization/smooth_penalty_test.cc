#include "core/optimization/smooth_penalty.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace topay {
namespace {

constexpr double kMu = 1e-3;

TEST(SmoothPenaltyTest, ZeroAtAndBelowZero) {
  for (double x : {-1.0, -1e-9, 0.0}) {
    const SmoothPenaltyValue p = SmoothPenalty(x, kMu);
    EXPECT_EQ(p.value, 0.0) << x;
    EXPECT_EQ(p.derivative, 0.0) << x;
  }
}

TEST(SmoothPenaltyTest, MatchesTheFactsSheetPieces) {
  for (double x : {1e-4, 5e-4, 9e-4}) {
    EXPECT_NEAR(SmoothPenalty(x, kMu).value,
                std::pow(x, 3) / (kMu * kMu) - std::pow(x, 4) / (2 * std::pow(kMu, 3)), 1e-18);
  }
  for (double x : {kMu, 2e-3, 1.0, 100.0}) {
    EXPECT_NEAR(SmoothPenalty(x, kMu).value, x - kMu / 2, 1e-15 * std::max(1.0, x));
    EXPECT_EQ(SmoothPenalty(x, kMu).derivative, 1.0);
  }
}

// Value and first derivative continuous at 0 and mu, and the second derivative too (C2):
// one-sided difference quotients of the derivative agree across each joint.
TEST(SmoothPenaltyTest, IsTwiceContinuouslyDifferentiableAtTheJoints) {
  constexpr double kH = 1e-9;
  for (double joint : {0.0, kMu}) {
    const SmoothPenaltyValue left = SmoothPenalty(joint - kH, kMu);
    const SmoothPenaltyValue right = SmoothPenalty(joint + kH, kMu);
    // The value changes by at most slope (<= 1) x 2h across the joint; the slope by O(h^2 / mu^2).
    EXPECT_LE(std::abs(right.value - left.value), 2 * kH * (1 + 1e-6));
    EXPECT_NEAR(left.derivative, right.derivative, 1e-9);
    const auto slope = [](double x) { return SmoothPenalty(x, kMu).derivative; };
    const double second_left = (slope(joint - kH) - slope(joint - 2 * kH)) / kH;
    const double second_right = (slope(joint + 2 * kH) - slope(joint + kH)) / kH;
    // L'' is 0 on both sides of both joints; the quotients see at most 6 x 2h / mu^2 of slope.
    EXPECT_NEAR(second_left, second_right, 6.0 * 2 * kH / (kMu * kMu) * 2);
    EXPECT_LT(std::abs(second_left), 0.05);
  }
}

TEST(SmoothPenaltyTest, DerivativeMatchesCentralDifferences) {
  constexpr double kH = 1e-8;
  for (double x : {1e-5, 3e-4, 7e-4, 0.999e-3, 1.5e-3, 0.3}) {
    const double numeric =
        (SmoothPenalty(x + kH, kMu).value - SmoothPenalty(x - kH, kMu).value) / (2 * kH);
    EXPECT_NEAR(SmoothPenalty(x, kMu).derivative, numeric, 1e-6) << x;
  }
}

TEST(SmoothPenaltyTest, NanStaysNan) {
  EXPECT_TRUE(std::isnan(SmoothPenalty(std::numeric_limits<double>::quiet_NaN(), kMu).value));
}

}  // namespace
}  // namespace topay
