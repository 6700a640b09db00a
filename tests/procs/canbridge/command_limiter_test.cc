// The bridge's command limiter: values clamped to the robot's limits, changes to the
// acceleration limits over the time since the last step (at most a cycle), checks of messages.
#include "procs/canbridge/command_limiter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace topay::canbridge {
namespace {

CommandLimits Limits() {
  CommandLimits limits;  // 1.0 m/s, 0.8 m/s^2, 0.9 rad/s, 1.0 rad/s^2
  limits.qd_max_radps = {2.0, 1.0};
  limits.qdd_max_radps2 = {10.0, 4.0};
  return limits;
}

TEST(CommandLimiterTest, RampsAtTheAccelerationLimitsUpToTheVelocityLimits) {
  CommandLimiter limiter(Limits(), 0.01);
  double t = 0.0;
  const DeviceCommand target{5.0, -5.0, {5.0, -0.5}};
  const DeviceCommand& first = limiter.Step(target, t);
  EXPECT_NEAR(first.v_mps, 0.008, 1e-12);        // 0.8 * 0.01
  EXPECT_NEAR(first.omega_radps, -0.01, 1e-12);  // 1.0 * 0.01
  EXPECT_NEAR(first.qdot_radps[0], 0.1, 1e-12);  // 10 * 0.01
  EXPECT_NEAR(first.qdot_radps[1], -0.04, 1e-12);
  for (int i = 0; i < 500; ++i) limiter.Step(target, t += 0.01);
  EXPECT_DOUBLE_EQ(limiter.last().v_mps, 1.0);
  EXPECT_DOUBLE_EQ(limiter.last().omega_radps, -0.9);
  EXPECT_DOUBLE_EQ(limiter.last().qdot_radps[0], 2.0);
  EXPECT_DOUBLE_EQ(limiter.last().qdot_radps[1], -0.5);
  EXPECT_GT(limiter.clamp_count(), 400);
}

TEST(CommandLimiterTest, ChangeScalesWithTheTimeSinceTheLastStepUpToOneCycle) {
  CommandLimiter limiter(Limits(), 0.01);
  limiter.Step({0.0, 0.0, {0.0, 0.0}}, 1.0);
  EXPECT_NEAR(limiter.Step({1.0, 0.0, {0.0, 0.0}}, 1.002).v_mps, 0.8 * 0.002, 1e-12);
  EXPECT_NEAR(limiter.Step({1.0, 0.0, {0.0, 0.0}}, 1.002).v_mps, 0.8 * 0.002, 1e-12);  // no time: no change
  EXPECT_NEAR(limiter.Step({1.0, 0.0, {0.0, 0.0}}, 2.0).v_mps, 0.8 * 0.012, 1e-12);    // a long gap: one cycle
  limiter.ResetToZero(3.0);
  EXPECT_EQ(limiter.last().v_mps, 0.0);
  EXPECT_NEAR(limiter.Step({-1.0, 0.0, {0.0, 0.0}}, 3.01).v_mps, -0.008, 1e-12);
}

TEST(CommandLimiterTest, WithinLimitsIsPassedThrough) {
  CommandLimiter limiter(Limits(), 0.01);
  limiter.Step({0.004, 0.002, {0.05, 0.0}}, 0.0);
  EXPECT_EQ(limiter.last().v_mps, 0.004);
  EXPECT_EQ(limiter.clamp_count(), 0);
}

TEST(CommandLimiterTest, ChecksMessages) {
  control_command_t msg{};
  msg.num_joints = 2;
  msg.qdot_radps = {0.1, 0.2};
  EXPECT_EQ(CheckControlCommand(msg, 2), "");
  EXPECT_NE(CheckControlCommand(msg, 7).find("num_joints 2, expected 7"), std::string::npos);
  msg.qdot_radps[1] = INFINITY;
  EXPECT_EQ(CheckControlCommand(msg, 2), "qdot_radps[1] is not finite");
  msg.qdot_radps[1] = 0.0;
  msg.omega_radps = NAN;
  EXPECT_EQ(CheckControlCommand(msg, 2), "omega_radps is not finite");
  msg.omega_radps = 0.0;
  msg.qdot_radps.resize(1);
  EXPECT_NE(CheckControlCommand(msg, 2), "");
  EXPECT_TRUE(IsZeroCommand({0.0005, -0.0005, {0.0}}, 1e-3));
  EXPECT_FALSE(IsZeroCommand({0.0, 0.0, {0.002}}, 1e-3));
}

TEST(CommandLimiterTest, RefusesBadLimits) {
  CommandLimits limits = Limits();
  limits.qdd_max_radps2.pop_back();
  EXPECT_THROW(CommandLimiter(limits, 0.01), std::invalid_argument);
  EXPECT_THROW(CommandLimiter(Limits(), 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace topay::canbridge
