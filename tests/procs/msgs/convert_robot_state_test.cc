// robot_state_t <-> RobotStateEstimate (procs/msgs/convert_robot_state.h): round trip through
// the encoded bytes, and the checks on inconsistent or non-finite messages.

#include "procs/msgs/convert_robot_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "topay_msgs/checked_decode.h"

namespace topay::msgs {
namespace {

RobotStateEstimate Sample() {
  RobotStateEstimate e;
  e.utime = 1'700'000'000'000'123;
  e.state.x_m = -1.25;
  e.state.y_m = 3.5;
  e.state.yaw_rad = 2.9;
  e.state.q_rad = (Eigen::VectorXd(7) << 0.1, -0.2, 0.3, -1.4, 0.5, 0.6, -0.7).finished();
  e.qdot_radps = (Eigen::VectorXd(7) << 0.01, 0.02, -0.03, 0.04, 0.05, -0.06, 0.07).finished();
  e.v_mps = 0.4;
  e.omega_radps = -0.3;
  e.joint_names = {"joint1", "joint2", "joint3", "joint4", "joint5", "joint6", "joint7"};
  e.gripper = 0.25;
  return e;
}

robot_state_t ThroughBytes(const robot_state_t& msg) {
  std::vector<std::uint8_t> bytes(msg.getEncodedSize());
  EXPECT_EQ(msg.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  std::string error;
  const auto decoded = CheckedDecode<robot_state_t>(bytes.data(), bytes.size(), &error);
  EXPECT_TRUE(decoded) << error;
  return *decoded;
}

TEST(ConvertRobotState, RoundTripsEveryField) {
  const RobotStateEstimate in = Sample();
  std::string error;
  const auto out = FromMessage(ThroughBytes(ToMessage(in)), &error);
  ASSERT_TRUE(out) << error;
  EXPECT_EQ(out->utime, in.utime);
  EXPECT_EQ(out->state.x_m, in.state.x_m);
  EXPECT_EQ(out->state.y_m, in.state.y_m);
  EXPECT_EQ(out->state.yaw_rad, in.state.yaw_rad);
  EXPECT_EQ(out->state.q_rad, in.state.q_rad);
  EXPECT_EQ(out->qdot_radps, in.qdot_radps);
  EXPECT_EQ(out->v_mps, in.v_mps);
  EXPECT_EQ(out->omega_radps, in.omega_radps);
  EXPECT_EQ(out->joint_names, in.joint_names);
  EXPECT_EQ(out->gripper, in.gripper);
}

TEST(ConvertRobotState, NamesJointsWhenTheEstimateHasNoNames) {
  RobotStateEstimate in = Sample();
  in.joint_names.clear();
  const robot_state_t msg = ToMessage(in);
  ASSERT_EQ(msg.joints.names.size(), 7u);
  EXPECT_EQ(msg.joints.names[0], "joint1");
  EXPECT_EQ(msg.joints.names[6], "joint7");
  EXPECT_TRUE(std::isnan(msg.joints.effort_Nm[3]));
}

TEST(ConvertRobotState, RejectsArraysThatDisagreeWithTheCount) {
  robot_state_t msg = ToMessage(Sample());
  msg.joints.velocity_radps.pop_back();
  std::string error;
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("num_joints"), std::string::npos);
}

TEST(ConvertRobotState, RejectsNonFiniteValues) {
  std::string error;
  robot_state_t msg = ToMessage(Sample());
  msg.pose.yaw_rad = NAN;
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("pose"), std::string::npos);
  msg = ToMessage(Sample());
  msg.joints.position_rad[2] = INFINITY;
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("joints"), std::string::npos);
}

}  // namespace
}  // namespace topay::msgs
