// topay-estimator's node logic, in-process with the times the test chooses: nothing is published
// until a pose, odometry and joints came; the content (pose predicted to the publish time,
// velocity, joints and gripper passed through with their stamps); publishing stops when
// odometry, joints or the pose go stale and resumes when fresh; bad inputs are counted per kind
// and change nothing; through the process loop on memq://, undecodable bytes never reach the
// node and ROBOT_STATE is published by the timer.

#include "procs/estimator/estimator_node.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "estimator_test_messages.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::estimator {
namespace {

using test::GripperMessage;
using test::JointMessage;
using test::PoseMessage;
using test::VelocityMessage;

constexpr std::int64_t kT0 = 1'700'000'000'000'000;  // a wall-clock utime
constexpr std::int64_t kMs = 1000;

int Fault(const EstimatorNode& node, InputFault fault) {
  return static_cast<int>(node.counts().faults[static_cast<int>(fault)]);
}

TEST(EstimatorNode, PublishesOnlyWithPoseOdometryAndJoints) {
  EstimatorNode node{EstimatorProcessOptions{}};
  EXPECT_EQ(node.Step(kT0), nullptr);
  EXPECT_EQ(node.validity(), Validity::kNoPose);
  EXPECT_EQ(node.Health(), heartbeat_t::WARN);
  node.OnPose(PoseMessage(kT0, 1.0, 2.0, 0.5), kT0);
  EXPECT_EQ(node.Step(kT0 + 1 * kMs), nullptr);
  EXPECT_EQ(node.validity(), Validity::kNoOdometry);
  node.OnVelocity(VelocityMessage(kT0 + 2 * kMs, 0.0, 0.0), kT0 + 2 * kMs);
  EXPECT_EQ(node.Step(kT0 + 3 * kMs), nullptr);
  EXPECT_EQ(node.validity(), Validity::kNoJoints);
  node.OnJoints(JointMessage(kT0 + 4 * kMs), kT0 + 4 * kMs);
  const robot_state_t* state = node.Step(kT0 + 5 * kMs);
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(node.validity(), Validity::kValid);
  EXPECT_EQ(node.Health(), heartbeat_t::OK);
  EXPECT_EQ(node.counts().published, 1);
  EXPECT_EQ(node.counts().held, 3);
  EXPECT_NE(node.StatusLine(kT0 + 5 * kMs).find("publishing"), std::string::npos);
}

TEST(EstimatorNode, ContentIsPredictedAndPassedThrough) {
  EstimatorNode node{EstimatorProcessOptions{}};
  node.OnPose(PoseMessage(kT0, 1.0, 2.0, 0.0), kT0);
  node.OnVelocity(VelocityMessage(kT0, 1.0, 0.0), kT0);
  node.OnJoints(JointMessage(kT0 + 10 * kMs, 0.2), kT0 + 10 * kMs);
  const std::int64_t now = kT0 + 50 * kMs;
  const robot_state_t* s = node.Step(now);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->utime, now);
  EXPECT_EQ(s->pose.utime, now);
  EXPECT_NEAR(s->pose.x_m, 1.05, 1e-9);  // 50 ms at 1 m/s
  EXPECT_NEAR(s->pose.y_m, 2.0, 1e-9);
  EXPECT_NEAR(s->pose.yaw_rad, 0.0, 1e-9);
  EXPECT_EQ(s->velocity.utime, kT0);
  EXPECT_DOUBLE_EQ(s->velocity.v_mps, 1.0);
  EXPECT_EQ(s->joints.utime, kT0 + 10 * kMs);
  ASSERT_EQ(s->joints.num_joints, 7);
  EXPECT_DOUBLE_EQ(s->joints.position_rad[6], 0.8);
  EXPECT_DOUBLE_EQ(s->joints.velocity_radps[6], 0.06);
  EXPECT_EQ(s->joints.names[0], "joint1");
  EXPECT_TRUE(std::isnan(s->gripper));  // no GRIPPER_STATE yet: unknown
  node.OnGripper(GripperMessage(now, 0.75), now);
  node.OnVelocity(VelocityMessage(now, 1.0, 0.0), now);
  node.OnJoints(JointMessage(now), now);
  s = node.Step(now + 10 * kMs);
  ASSERT_NE(s, nullptr);
  EXPECT_DOUBLE_EQ(s->gripper, 0.75);
  EXPECT_NEAR(s->pose.x_m, 1.06, 1e-9);
  // The gripper goes stale (0.5 s) while the rest stays fresh: unknown again, still published.
  std::int64_t t = now;
  for (; t < now + 600 * kMs; t += 10 * kMs) {
    node.OnVelocity(VelocityMessage(t + 10 * kMs, 0.0, 0.0), t + 10 * kMs);
    node.OnJoints(JointMessage(t + 10 * kMs), t + 10 * kMs);
  }
  s = node.Step(t);
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(std::isnan(s->gripper));
}

TEST(EstimatorNode, StopsWhenInputsGoStaleAndResumes) {
  const EstimatorProcessOptions options;
  EstimatorNode node{options};
  node.OnPose(PoseMessage(kT0, 0.0, 0.0, 0.0), kT0);
  node.OnVelocity(VelocityMessage(kT0, 0.0, 0.0), kT0);
  node.OnJoints(JointMessage(kT0), kT0);
  ASSERT_NE(node.Step(kT0 + 10 * kMs), nullptr);
  // Odometry older than odometry_timeout_s (the joints kept fresh): held.
  const std::int64_t late = kT0 + static_cast<std::int64_t>(options.odometry_timeout_s * 1e6) + 10 * kMs;
  node.OnJoints(JointMessage(late), late);
  EXPECT_EQ(node.Step(late), nullptr);
  EXPECT_EQ(node.validity(), Validity::kOdometryStale);
  EXPECT_EQ(node.Health(), heartbeat_t::WARN);
  node.OnVelocity(VelocityMessage(late, 0.0, 0.0), late);
  EXPECT_NE(node.Step(late + kMs), nullptr);
  // Joints older than joints_timeout_s.
  const std::int64_t later = late + static_cast<std::int64_t>(options.joints_timeout_s * 1e6) + 10 * kMs;
  node.OnVelocity(VelocityMessage(later, 0.0, 0.0), later);
  EXPECT_EQ(node.Step(later), nullptr);
  EXPECT_EQ(node.validity(), Validity::kJointsStale);
  node.OnJoints(JointMessage(later), later);
  EXPECT_NE(node.Step(later + kMs), nullptr);
  // No pose for longer than pose_timeout_s (odometry and joints fresh): held.
  const std::int64_t no_pose = kT0 + static_cast<std::int64_t>(options.pose_timeout_s * 1e6) + 10 * kMs;
  node.OnVelocity(VelocityMessage(no_pose, 0.0, 0.0), no_pose);
  node.OnJoints(JointMessage(no_pose), no_pose);
  EXPECT_EQ(node.Step(no_pose), nullptr);
  EXPECT_EQ(node.validity(), Validity::kPoseStale);
  EXPECT_EQ(node.counts().invalidations, 3);
  EXPECT_NE(node.Report().find("3 invalidations"), std::string::npos) << node.Report();
}

TEST(EstimatorNode, BadInputIsCountedPerKindAndChangesNothing) {
  EstimatorNode node{EstimatorProcessOptions{}};
  node.OnPose(PoseMessage(kT0, 1.0, 1.0, 0.0), kT0);
  node.OnVelocity(VelocityMessage(kT0, 0.0, 0.0), kT0);
  node.OnJoints(JointMessage(kT0), kT0);
  const robot_state_t before = *node.Step(kT0 + kMs);
  const double nan = std::nan("");
  const std::int64_t now = kT0 + 2 * kMs;
  node.OnPose(PoseMessage(now, nan, 1.0, 0.0), now);
  node.OnPose(PoseMessage(now, 1.0, 1.0, nan), now);
  node.OnPose(PoseMessage(now + 200 * kMs, 5.0, 5.0, 0.0), now);  // from the future
  node.OnPose(PoseMessage(kT0, 1.0, 1.0, 0.0), now);              // not after the last one
  node.OnVelocity(VelocityMessage(now, nan, 0.0), now);
  node.OnVelocity(VelocityMessage(kT0 - kMs, 0.3, 0.0), now);     // dt < 0
  node.OnVelocity(VelocityMessage(now, 0.2, 235.0), now);         // a corrupted omega (finding 27)
  node.OnJoints(JointMessage(now, nan), now);
  node.OnJoints(JointMessage(now, 0.0, 6), now);                  // 6 joints, the robot has 7
  joint_state_t malformed = JointMessage(now);
  malformed.position_rad.pop_back();
  node.OnJoints(malformed, now);
  node.OnJoints(JointMessage(kT0 - kMs, 0.5), now);               // older than the last one
  node.OnJoints(JointMessage(now, 1.5), now);                     // 1.5 rad in 2 ms: a jump
  node.OnGripper(GripperMessage(now, 2.0), now);
  EXPECT_EQ(Fault(node, InputFault::kPoseNotFinite), 2);
  EXPECT_EQ(Fault(node, InputFault::kPoseFuture), 1);
  EXPECT_EQ(Fault(node, InputFault::kPoseOutOfOrder), 1);
  EXPECT_EQ(Fault(node, InputFault::kVelocityNotFinite), 1);
  EXPECT_EQ(Fault(node, InputFault::kVelocityOutOfOrder), 1);
  EXPECT_EQ(Fault(node, InputFault::kVelocityImplausible), 1);
  EXPECT_EQ(Fault(node, InputFault::kJointsNotFinite), 1);
  EXPECT_EQ(Fault(node, InputFault::kJointsCount), 1);
  EXPECT_EQ(Fault(node, InputFault::kJointsMalformed), 1);
  EXPECT_EQ(Fault(node, InputFault::kJointsOutOfOrder), 1);
  EXPECT_EQ(Fault(node, InputFault::kJointsJump), 1);
  EXPECT_EQ(Fault(node, InputFault::kGripperRange), 1);
  EXPECT_EQ(node.counts().total_faults(), 13);
  const robot_state_t* after = node.Step(kT0 + kMs + 1);
  ASSERT_NE(after, nullptr);
  EXPECT_NEAR(after->pose.x_m, before.pose.x_m, 1e-9);
  EXPECT_NEAR(after->pose.y_m, before.pose.y_m, 1e-9);
  EXPECT_EQ(after->joints.position_rad, before.joints.position_rad);
  EXPECT_TRUE(std::isnan(after->gripper));
  EXPECT_NE(node.Report().find("2 BASE_POSE not finite"), std::string::npos) << node.Report();
  EXPECT_NE(node.StatusLine(now).find("13 bad inputs"), std::string::npos) << node.StatusLine(now);
}

// A delayed pose (stamped before the odometry already taken) is applied at its time.
TEST(EstimatorNode, DelayedPoseIsAppliedAtItsTime) {
  EstimatorNode node{EstimatorProcessOptions{}};
  node.OnPose(PoseMessage(kT0, 0.0, 0.0, 0.0), kT0);
  for (int k = 0; k <= 20; ++k) node.OnVelocity(VelocityMessage(kT0 + k * 5 * kMs, 1.0, 0.0), kT0 + k * 5 * kMs);
  node.OnJoints(JointMessage(kT0 + 100 * kMs), kT0 + 100 * kMs);
  // The localisation says the robot was 2 cm further at 50 ms (measured then, arriving now).
  node.OnPose(PoseMessage(kT0 + 50 * kMs, 0.07, 0.0, 0.0), kT0 + 100 * kMs);
  EXPECT_EQ(node.filter().summary().delayed_inputs, 1);
  const robot_state_t* s = node.Step(kT0 + 100 * kMs);
  ASSERT_NE(s, nullptr);
  EXPECT_GT(s->pose.x_m, 0.1 + 0.005);  // pulled forward by the delayed pose
  EXPECT_LT(s->pose.x_m, 0.1 + 0.02);
}

TEST(EstimatorNode, ThroughTheProcessLoop) {
  procs::ProcessOptions process;
  process.lcm_url = "memq://";
  process.name = "estimator-test";
  procs::ProcessLoop loop(process);
  ASSERT_TRUE(loop.ok());
  EstimatorNode node{EstimatorProcessOptions{}};
  ConnectEstimatorNode(&loop, &node, 0.01);
  const std::vector<std::uint8_t> garbage = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  for (const char* channel : {"BASE_POSE", "BASE_VELOCITY", "JOINT_STATE", "GRIPPER_STATE"}) {
    loop.lcm().publish(channel, garbage.data(), static_cast<unsigned>(garbage.size()));
  }
  struct Count {
    int states = 0;
    void On(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t*) { ++states; }
  } count;
  loop.lcm().subscribe(std::string(channels::ROBOT_STATE), &Count::On, &count);
  const std::int64_t now = procs::NowUtime();
  const base_pose_t pose = PoseMessage(now, 1.0, 2.0, 0.3);
  const base_velocity_t velocity = VelocityMessage(now, 0.0, 0.0);
  const joint_state_t joints = JointMessage(now);
  loop.lcm().publish(std::string(channels::BASE_POSE), &pose);
  loop.lcm().publish(std::string(channels::BASE_VELOCITY), &velocity);
  loop.lcm().publish(std::string(channels::JOINT_STATE), &joints);
  loop.RunUntil(procs::ProcessLoop::Clock::now() + std::chrono::milliseconds(60));
  EXPECT_EQ(loop.stats().Of("BASE_POSE").malformed, 1);
  EXPECT_EQ(loop.stats().Of("BASE_VELOCITY").malformed, 1);
  EXPECT_EQ(loop.stats().Of("JOINT_STATE").malformed, 1);
  EXPECT_EQ(loop.stats().Of("GRIPPER_STATE").malformed, 1);
  EXPECT_EQ(node.counts().poses, 1);
  EXPECT_EQ(node.counts().velocities, 1);
  EXPECT_EQ(node.counts().joints, 1);
  EXPECT_GE(node.counts().published, 1);  // within the 0.1 s timeouts of the inputs' stamps
  EXPECT_GE(count.states, 1);  // on the bus (the last one may not be handled yet)
  EXPECT_LE(count.states, node.counts().published);
}

}  // namespace
}  // namespace topay::estimator
