#include "core/optimization/time_map.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(TimeMapTest, MatchesTheFactsSheetFormula) {
  EXPECT_DOUBLE_EQ(DurationFromTau(0.0), 1.0);
  EXPECT_DOUBLE_EQ(DurationFromTau(2.0), 2.0 + 2.0 + 1.0);         // tau^2/2 + tau + 1
  EXPECT_DOUBLE_EQ(DurationFromTau(-2.0), 1.0 / (2.0 + 2.0 + 1.0));  // 1 / (tau^2/2 - tau + 1)
}

TEST(TimeMapTest, InverseIsThePapersLc2) {
  for (double T : {1e-3, 0.1, 0.5, 1.0, 1.5, 3.0, 40.0}) {
    const double tau = TauFromDuration(T);
    EXPECT_NEAR(DurationFromTau(tau), T, 1e-12 * std::max(1.0, T)) << T;
    // Eq. (21) directly.
    const double expected = T > 1.0 ? std::sqrt(2 * T - 1) - 1 : 1 - std::sqrt(2 / T - 1);
    EXPECT_DOUBLE_EQ(tau, expected);
  }
}

TEST(TimeMapTest, DerivativeMatchesCentralDifferencesAndIsContinuousAtZero) {
  constexpr double kH = 1e-6;
  for (double tau : {-30.0, -2.0, -0.3, -1e-3, 1e-3, 0.7, 5.0}) {
    double analytic = 0.0;
    DurationFromTau(tau, &analytic);
    const double numeric = (DurationFromTau(tau + kH) - DurationFromTau(tau - kH)) / (2 * kH);
    EXPECT_NEAR(analytic, numeric, 1e-7 * std::max(1.0, std::abs(numeric))) << tau;
    EXPECT_GT(analytic, 0.0);
  }
  double left = 0.0, right = 0.0;
  DurationFromTau(-1e-12, &left);
  DurationFromTau(1e-12, &right);
  EXPECT_NEAR(left, right, 1e-9);
}

TEST(TimeMapTest, AlwaysPositive) {
  for (double tau : {-1e6, -100.0, 0.0, 100.0}) EXPECT_GT(DurationFromTau(tau), 0.0);
}

TEST(TimeMapTest, RejectsNonPositiveOrNonFiniteDurations) {
  for (double T : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(TauFromDuration(T), std::invalid_argument) << T;
  }
}

}  // namespace
}  // namespace topay
