#include "core/validate/limit_ratios.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/common/random.h"

namespace topay {
namespace {

constexpr int kJoints = 3;

BaseLimits Base() {
  BaseLimits base;
  base.v_max_mps = 1.0;
  base.a_max_mps2 = 0.8;
  base.omega_max_radps = 1.25;
  base.beta_max_radps2 = 1.0;
  return base;
}

JointLimits Joints() {
  JointLimits joints;
  joints.q_min_rad = Eigen::Vector3d(-1.0, -2.0, 0.5);
  joints.q_max_rad = Eigen::Vector3d(1.0, 1.0, 2.5);
  joints.qd_max_radps = Eigen::Vector3d(2.0, 2.0, 1.0);
  joints.qdd_max_radps2 = Eigen::Vector3d(4.0, 4.0, 5.0);
  return joints;
}

TrajectorySample Still() {
  TrajectorySample sample = MakeTrajectorySample(kJoints);
  sample.state.q_rad = Eigen::Vector3d(0.0, -0.5, 1.5);  // every joint at mid-range
  return sample;
}

TEST(WorstRateRatioTest, EachLimitIsNamedWithItsRatio) {
  struct Case {
    double TrajectorySample::*field;
    double value;
    Limit limit;
    double ratio;
  };
  // v and omega alone also set the coupled ratio to the same value: the tie goes to the
  // box limit (earlier in Limit order).
  const Case cases[] = {
      {&TrajectorySample::v_mps, -0.9, Limit::kLinearVelocity, 0.9},
      {&TrajectorySample::omega_radps, 1.0, Limit::kYawRate, 0.8},
      {&TrajectorySample::a_mps2, -1.2, Limit::kLinearAcceleration, 1.5},
      {&TrajectorySample::beta_radps2, 0.5, Limit::kYawAcceleration, 0.5},
  };
  for (const Case& c : cases) {
    TrajectorySample sample = Still();
    sample.*c.field = c.value;
    const LimitRatio worst = WorstRateRatio(sample, Base(), Joints());
    EXPECT_EQ(worst.limit, c.limit) << ToString(c.limit);
    EXPECT_DOUBLE_EQ(worst.ratio, c.ratio) << ToString(c.limit);
    EXPECT_EQ(worst.joint, -1);
    EXPECT_DOUBLE_EQ(worst.value, c.value);
  }
  TrajectorySample sample = Still();
  sample.qd_radps(2) = -0.7;  // 0.7 / 1.0
  sample.qdd_radps2(1) = 2.0;  // 0.5
  LimitRatio worst = WorstRateRatio(sample, Base(), Joints());
  EXPECT_EQ(worst.limit, Limit::kJointVelocity);
  EXPECT_EQ(worst.joint, 2);
  EXPECT_DOUBLE_EQ(worst.ratio, 0.7);
  EXPECT_DOUBLE_EQ(worst.bound, 1.0);
  sample.qdd_radps2(2) = -4.5;  // 0.9
  worst = WorstRateRatio(sample, Base(), Joints());
  EXPECT_EQ(worst.limit, Limit::kJointAcceleration);
  EXPECT_EQ(worst.joint, 2);
  EXPECT_DOUBLE_EQ(worst.ratio, 0.9);
}

TEST(WorstRateRatioTest, CoupledRatioIsEquationNineOverVmaxOmegaMax) {
  const BaseLimits base = Base();
  Rng rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    TrajectorySample sample = Still();
    sample.v_mps = rng.Uniform(-1.0, 1.0);
    sample.omega_radps = rng.Uniform(-1.25, 1.25);
    const LimitRatio worst = WorstRateRatio(sample, base, Joints());
    // Eq. (9) as printed: |v_max omega +- omega_max v| <= v_max omega_max.
    const double vw = base.v_max_mps * base.omega_max_radps;
    const double plus = std::abs(base.v_max_mps * sample.omega_radps +
                                 base.omega_max_radps * sample.v_mps) / vw;
    const double minus = std::abs(base.v_max_mps * sample.omega_radps -
                                  base.omega_max_radps * sample.v_mps) / vw;
    // Within the box, the coupled ratio |v|/v_max + |omega|/omega_max is always the worst.
    EXPECT_EQ(worst.limit, Limit::kCoupledVelocity);
    EXPECT_NEAR(worst.ratio, std::max(plus, minus), 1e-12);
  }
  // Both at 60 % of their limits: 1.2 coupled.
  TrajectorySample sample = Still();
  sample.v_mps = -0.6;
  sample.omega_radps = 0.75;
  EXPECT_NEAR(WorstRateRatio(sample, base, Joints()).ratio, 1.2, 1e-12);
}

TEST(WorstJointPositionRatioTest, RatioIsOneOnEitherLimitOfAsymmetricRanges) {
  const JointLimits joints = Joints();
  // Joint 1 range [-2, 1]: mid -0.5, half 1.5.
  LimitRatio worst = WorstJointPositionRatio(Eigen::Vector3d(0.0, -2.0, 1.5), joints);
  EXPECT_EQ(worst.limit, Limit::kJointPosition);
  EXPECT_EQ(worst.joint, 1);
  EXPECT_DOUBLE_EQ(worst.ratio, 1.0);
  EXPECT_DOUBLE_EQ(worst.bound, -2.0);
  // Joint 2 range [0.5, 2.5] at 2.7: 1.2 / 1.0.
  worst = WorstJointPositionRatio(Eigen::Vector3d(0.5, -0.5, 2.7), joints);
  EXPECT_EQ(worst.joint, 2);
  EXPECT_NEAR(worst.ratio, 1.2, 1e-12);
  EXPECT_DOUBLE_EQ(worst.bound, 2.5);
}

TEST(MaxJointPositionExcessTest, SignedDistanceBeyondTheNearestLimit) {
  const JointLimits joints = Joints();
  int joint = -1;
  EXPECT_NEAR(MaxJointPositionExcess(Eigen::Vector3d(0.0, -0.5, 1.5), joints, &joint), -1.0,
              1e-12);  // every joint at least 1 rad inside; joint 0 first
  EXPECT_EQ(joint, 0);
  EXPECT_NEAR(MaxJointPositionExcess(Eigen::Vector3d(0.9, -2.3, 2.45), joints, &joint), 0.3,
              1e-12);
  EXPECT_EQ(joint, 1);
  EXPECT_NEAR(MaxJointPositionExcess(Eigen::Vector3d(0.9, 0.0, 0.4), joints, &joint), 0.1,
              1e-12);
  EXPECT_EQ(joint, 2);
}

TEST(CheckKinematicLimitsTest, NamesTheBadField) {
  const auto message_of = [](const BaseLimits& base, const JointLimits& joints) {
    try {
      CheckKinematicLimits(base, joints, kJoints);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(message_of(Base(), Joints()), "");
  BaseLimits base = Base();
  base.beta_max_radps2 = 0.0;
  EXPECT_NE(message_of(base, Joints()).find("beta_max_radps2"), std::string::npos);
  base = Base();
  base.v_max_mps = std::numeric_limits<double>::infinity();
  EXPECT_NE(message_of(base, Joints()).find("v_max_mps"), std::string::npos);
  JointLimits joints = Joints();
  joints.qd_max_radps.resize(2);
  EXPECT_NE(message_of(Base(), joints).find("qd_max_radps has 2 entries, expected 3"),
            std::string::npos);
  joints = Joints();
  joints.q_min_rad(2) = 3.0;
  EXPECT_NE(message_of(Base(), joints).find("joint index 2"), std::string::npos);
  joints = Joints();
  joints.qdd_max_radps2(1) = -1.0;
  EXPECT_NE(message_of(Base(), joints).find("qdd_max_radps2 of joint index 1"), std::string::npos);
}

}  // namespace
}  // namespace topay
