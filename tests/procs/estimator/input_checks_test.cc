// The estimator's input checks: NaN or infinite values, arrays that disagree with num_joints,
// a wrong joint count, a missing or out-of-range gripper.

#include "procs/estimator/input_checks.h"

#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <string>

namespace topay::estimator {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

joint_state_t Joints(int n) {
  joint_state_t m;
  m.utime = 1;
  m.num_joints = n;
  for (int j = 0; j < n; ++j) {
    m.names.push_back("joint" + std::to_string(j + 1));
    m.position_rad.push_back(0.1 * j);
    m.velocity_radps.push_back(0.0);
    m.effort_Nm.push_back(kNan);  // not measured: allowed
  }
  return m;
}

TEST(EstimatorInputChecks, PoseAndVelocity) {
  base_pose_t pose{};
  EXPECT_FALSE(CheckPose(pose));
  pose.yaw_rad = kNan;
  EXPECT_EQ(CheckPose(pose), InputFault::kPoseNotFinite);
  base_velocity_t velocity{};
  EXPECT_FALSE(CheckVelocity(velocity, 2.0, 4.0));
  velocity.v_mps = -1.9;
  velocity.omega_radps = 3.9;
  EXPECT_FALSE(CheckVelocity(velocity, 2.0, 4.0));
  velocity.omega_radps = 235.0;  // a bit-flipped exponent (finding 27)
  EXPECT_EQ(CheckVelocity(velocity, 2.0, 4.0), InputFault::kVelocityImplausible);
  velocity.omega_radps = 0.0;
  velocity.v_mps = -2.5;
  EXPECT_EQ(CheckVelocity(velocity, 2.0, 4.0), InputFault::kVelocityImplausible);
  velocity.omega_radps = std::numeric_limits<double>::infinity();
  EXPECT_EQ(CheckVelocity(velocity, 2.0, 4.0), InputFault::kVelocityNotFinite);
}

TEST(EstimatorInputChecks, Joints) {
  EXPECT_FALSE(CheckJoints(Joints(7), 7));
  EXPECT_FALSE(CheckJoints(Joints(6), 0));  // any count
  EXPECT_EQ(CheckJoints(Joints(6), 7), InputFault::kJointsCount);
  joint_state_t short_names = Joints(7);
  short_names.names.pop_back();
  EXPECT_EQ(CheckJoints(short_names, 7), InputFault::kJointsMalformed);
  joint_state_t negative = Joints(0);
  negative.num_joints = -1;
  EXPECT_EQ(CheckJoints(negative, 0), InputFault::kJointsMalformed);
  joint_state_t nan = Joints(7);
  nan.velocity_radps[3] = kNan;
  EXPECT_EQ(CheckJoints(nan, 7), InputFault::kJointsNotFinite);
}

TEST(EstimatorInputChecks, Gripper) {
  joint_state_t g = Joints(1);
  double position = -1.0;
  EXPECT_EQ(GripperPosition(g, &position), InputFault::kGripperMalformed);  // named joint1
  g.names[0] = "gripper";
  g.position_rad[0] = 0.7;
  EXPECT_FALSE(GripperPosition(g, &position));
  EXPECT_DOUBLE_EQ(position, 0.7);
  g.position_rad[0] = 1.2;
  EXPECT_EQ(GripperPosition(g, &position), InputFault::kGripperRange);
  g.position_rad[0] = kNan;
  EXPECT_EQ(GripperPosition(g, &position), InputFault::kGripperRange);
}

TEST(EstimatorInputChecks, EveryFaultHasItsOwnName) {
  std::set<std::string> names;
  for (int k = 0; k < kNumInputFaults; ++k) names.insert(InputFaultName(static_cast<InputFault>(k)));
  EXPECT_EQ(static_cast<int>(names.size()), kNumInputFaults);
  EXPECT_EQ(names.count("?"), 0u);
}

}  // namespace
}  // namespace topay::estimator
