#include "core/optimization/joint_map.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/optimization/time_map.h"

namespace topay {
namespace {

TEST(JointMapTest, EveryXiMapsStrictlyInsideTheLimits) {
  for (double xi = -1e4; xi <= 1e4; xi *= -0.5) {
    const double q = JointFromXi(xi, -2.26, 2.26);
    EXPECT_GT(q, -2.26) << xi;
    EXPECT_LT(q, 2.26) << xi;
    if (std::abs(xi) < 1e-3) break;
  }
  EXPECT_DOUBLE_EQ(JointFromXi(0.0, -1.0, 3.0), 1.0);  // middle of the range
}

TEST(JointMapTest, SymmetricLimitsGiveThePapersFormula) {
  const double q_max = 2.355;
  for (double q : {-2.3, -1.0, 0.0, 0.4, 2.35}) {
    // Eq. (22): xi = L_c2((q_max + q) / (q_max - q)).
    EXPECT_NEAR(XiFromJoint(q, -q_max, q_max), TauFromDuration((q_max + q) / (q_max - q)), 1e-12);
  }
}

TEST(JointMapTest, InverseRoundTrips) {
  for (double q : {-3.09, -1.0, 0.0, 0.3, 2.5, 3.09}) {
    EXPECT_NEAR(JointFromXi(XiFromJoint(q, -3.1, 3.1), -3.1, 3.1), q, 1e-12) << q;
  }
  // Asymmetric limits too.
  for (double q : {-0.4, 0.0, 1.9}) {
    EXPECT_NEAR(JointFromXi(XiFromJoint(q, -0.5, 2.0), -0.5, 2.0), q, 1e-12) << q;
  }
}

TEST(JointMapTest, ValuesOnOrPastALimitMapToAFiniteInteriorXi) {
  for (double q : {-3.1, 3.1, 5.0, -7.0}) {
    const double xi = XiFromJoint(q, -3.1, 3.1);
    EXPECT_TRUE(std::isfinite(xi));
    const double back = JointFromXi(xi, -3.1, 3.1);
    EXPECT_GT(back, -3.1);
    EXPECT_LT(back, 3.1);
    EXPECT_NEAR(std::abs(back), 3.1, 1e-5);
  }
}

TEST(JointMapTest, DerivativeMatchesCentralDifferences) {
  constexpr double kH = 1e-6;
  for (double xi : {-20.0, -1.5, -0.1, 0.0, 0.2, 3.0, 40.0}) {
    double analytic = 0.0;
    JointFromXi(xi, -0.5, 2.0, &analytic);
    const double numeric =
        (JointFromXi(xi + kH, -0.5, 2.0) - JointFromXi(xi - kH, -0.5, 2.0)) / (2 * kH);
    EXPECT_NEAR(analytic, numeric, 1e-8) << xi;
    EXPECT_GT(analytic, 0.0) << xi;
  }
}

TEST(JointMapTest, RejectsBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(XiFromJoint(nan, -1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(XiFromJoint(0.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(XiFromJoint(0.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(XiFromJoint(0.0, nan, 1.0), std::invalid_argument);
  EXPECT_THROW(XiFromJoint(0.0, -1.0, 1.0, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace topay
