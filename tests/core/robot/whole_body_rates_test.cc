#include "core/robot/whole_body_rates.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/robot/moving_state.h"

namespace topay {
namespace {

TEST(WholeBodyRatesTest, DefaultIsAtRestForAnyJointCount) {
  const WholeBodyRates rates;
  EXPECT_TRUE(rates.IsAtRest());
  EXPECT_TRUE(rates.IsFinite());
  EXPECT_TRUE(rates.HasJointCount(7));
  EXPECT_TRUE(rates.HasJointCount(0));
  EXPECT_EQ(rates.JointVelocities(7), Eigen::VectorXd::Zero(7));
  EXPECT_EQ(rates.JointAccelerations(3), Eigen::VectorXd::Zero(3));
  const MovingState moving;
  EXPECT_TRUE(moving.rates.IsAtRest());
}

TEST(WholeBodyRatesTest, ZeroIsSizedAndAtRest) {
  const WholeBodyRates rates = WholeBodyRates::Zero(7);
  EXPECT_EQ(rates.qd_radps.size(), 7);
  EXPECT_EQ(rates.qdd_radps2.size(), 7);
  EXPECT_TRUE(rates.IsAtRest());
  EXPECT_TRUE(rates.HasJointCount(7));
  EXPECT_FALSE(rates.HasJointCount(6));
}

TEST(WholeBodyRatesTest, AnyNonZeroRateIsMotion) {
  for (int which = 0; which < 6; ++which) {
    WholeBodyRates rates = WholeBodyRates::Zero(7);
    switch (which) {
      case 0: rates.v_mps = 0.5; break;
      case 1: rates.omega_radps = -0.1; break;
      case 2: rates.a_mps2 = 0.2; break;
      case 3: rates.beta_radps2 = 0.3; break;
      case 4: rates.qd_radps(6) = -0.01; break;
      case 5: rates.qdd_radps2(0) = 0.01; break;
    }
    EXPECT_FALSE(rates.IsAtRest()) << which;
    EXPECT_TRUE(rates.IsAtRest(0.6)) << which;
    EXPECT_EQ(rates.JointVelocities(7), rates.qd_radps);
  }
}

TEST(WholeBodyRatesTest, NonFiniteIsNeitherFiniteNorAtRest) {
  WholeBodyRates rates = WholeBodyRates::Zero(7);
  rates.qdd_radps2(3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(rates.IsFinite());
  EXPECT_FALSE(rates.IsAtRest(1e9));
  rates = WholeBodyRates::Zero(7);
  rates.v_mps = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(rates.IsFinite());
  EXPECT_FALSE(rates.IsAtRest(1e9));
}

}  // namespace
}  // namespace topay
