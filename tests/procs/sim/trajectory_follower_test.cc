// The ideal follower of topay-sim --follow (procs/sim/trajectory_follower.h): holds before the
// start, follows with the trajectory's velocities, holds the end at rest; rejects malformed
// trajectories, non-MINCO coefficients and far starts (counted, the robot unchanged); a new
// trajectory takes over at its own start.

#include "procs/sim/trajectory_follower.h"

#include <gtest/gtest.h>

#include <cmath>

#include "follow_test_trajectory.h"

namespace topay::simproc {
namespace {

constexpr int kJoints = 7;
constexpr std::int64_t kStart = 1'800'000'000'000'000;

sim::PlantState Robot() {
  sim::PlantState s;
  s.state.x_m = 2.0;
  s.state.y_m = -1.0;
  s.state.yaw_rad = 0.4;
  s.state.q_rad = Eigen::VectorXd::LinSpaced(kJoints, -0.3, 0.3);
  s.qdot_radps = Eigen::VectorXd::Zero(kJoints);
  s.gripper = 0.25;
  return s;
}

ArcYawTrajectory TrajectoryFrom(const sim::PlantState& robot) {
  return test::FollowTestTrajectory({robot.state.x_m, robot.state.y_m}, robot.state.yaw_rad, robot.state.q_rad);
}

poly_trajectory_t MessageFrom(const sim::PlantState& robot, std::int64_t start_utime, std::int64_t id = 5) {
  return test::FollowTestMessage(TrajectoryFrom(robot), {robot.state.x_m, robot.state.y_m}, start_utime, id);
}

std::int64_t At(double t_s) { return kStart + std::llround(t_s * 1e6); }

void ExpectAtRestAt(const sim::PlantState& s, const sim::PlantState& where) {
  EXPECT_EQ(s.state.x_m, where.state.x_m);
  EXPECT_EQ(s.state.y_m, where.state.y_m);
  EXPECT_EQ(s.state.yaw_rad, where.state.yaw_rad);
  EXPECT_EQ(s.state.q_rad, where.state.q_rad);
  EXPECT_EQ(s.v_mps, 0.0);
  EXPECT_EQ(s.omega_radps, 0.0);
  EXPECT_TRUE(s.qdot_radps.isZero());
}

TEST(TrajectoryFollower, HoldsWithoutATrajectory) {
  TrajectoryFollower follower(kJoints, {});
  sim::PlantState moving = Robot();
  moving.v_mps = 0.3;
  ExpectAtRestAt(follower.StateAt(At(0.0), moving), Robot());
  EXPECT_FALSE(follower.active_id());
}

TEST(TrajectoryFollower, HoldsUntilTheStartFollowsWithVelocitiesAndHoldsTheEndAtRest) {
  TrajectoryFollower follower(kJoints, {});
  const sim::PlantState robot = Robot();
  ASSERT_EQ(follower.Accept(MessageFrom(robot, kStart), At(-0.5), robot), "");
  EXPECT_EQ(follower.counts().accepted, 1);
  // Before the start: the robot where it is, at rest.
  ExpectAtRestAt(follower.StateAt(At(-0.1), robot), robot);
  EXPECT_FALSE(follower.active_id());

  const ArcYawTrajectory expected = TrajectoryFrom(robot);
  TrajectorySample point = expected.MakePoint();
  sim::PlantState state = robot;
  for (double t = 0.0; t < expected.duration_s(); t += 0.002) {
    SCOPED_TRACE(t);
    state = follower.StateAt(At(t), state);
    expected.Evaluate(static_cast<double>(At(t) - kStart) * 1e-6, &point);
    EXPECT_NEAR(state.state.x_m, point.state.x_m, 1e-9);
    EXPECT_NEAR(state.state.y_m, point.state.y_m, 1e-9);
    EXPECT_NEAR(state.state.yaw_rad, point.state.yaw_rad, 1e-9);
    EXPECT_NEAR(state.v_mps, point.v_mps, 1e-9);
    EXPECT_NEAR(state.omega_radps, point.omega_radps, 1e-9);
    EXPECT_LE((state.state.q_rad - point.state.q_rad).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LE((state.qdot_radps - point.qd_radps).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_EQ(state.gripper, 0.25);
  }
  EXPECT_EQ(follower.active_id(), 5);
  // Mid-way it moves for real.
  state = follower.StateAt(At(1.0), state);
  EXPECT_GT(state.v_mps, 0.3);
  EXPECT_GT(state.omega_radps, 0.1);
  // After the end: the end state, at rest, for good.
  expected.Evaluate(expected.duration_s(), &point);
  for (const double t : {2.0, 2.5, 60.0}) {
    state = follower.StateAt(At(t), state);
    EXPECT_NEAR(state.state.x_m, point.state.x_m, 1e-12);
    EXPECT_NEAR(state.state.yaw_rad, robot.state.yaw_rad + 0.5, 1e-12);
    EXPECT_NEAR(std::hypot(state.state.x_m - robot.state.x_m, state.state.y_m - robot.state.y_m), 0.98, 0.02);
    EXPECT_EQ(state.v_mps, 0.0);
    EXPECT_EQ(state.omega_radps, 0.0);
    EXPECT_TRUE(state.qdot_radps.isZero());
  }
}

TEST(TrajectoryFollower, RejectsMalformedAndFarTrajectoriesAndKeepsHolding) {
  TrajectoryFollower follower(kJoints, {});
  const sim::PlantState robot = Robot();
  const poly_trajectory_t good = MessageFrom(robot, kStart);
  const auto rejected = [&](poly_trajectory_t msg, const sim::PlantState& current = Robot()) {
    return follower.Accept(msg, At(-0.5), current);
  };
  poly_trajectory_t msg = good;
  msg.num_joints = 6;
  EXPECT_NE(rejected(msg).find("num_joints 6, the robot has 7"), std::string::npos);
  msg = good;
  msg.coeffs[40] = NAN;
  EXPECT_NE(rejected(msg).find("not finite"), std::string::npos);
  msg = good;
  msg.num_coeffs -= 1;
  msg.coeffs.pop_back();
  EXPECT_NE(rejected(msg).find("num_coeffs"), std::string::npos);
  msg = good;
  msg.coeffs[(1 * 9 + 3) * 6 + 4] += 0.05;  // piece 1, joint 2, t^4: no longer MINCO's
  EXPECT_NE(rejected(msg).find("trajectory 5 (goal 1): not a MINCO s = 3 trajectory"), std::string::npos)
      << rejected(msg);
  msg = good;
  msg.yaw0_rad += 0.2;
  EXPECT_NE(rejected(msg).find("yaw0_rad"), std::string::npos);
  sim::PlantState elsewhere = robot;
  elsewhere.state.x_m += 0.4;
  EXPECT_NE(rejected(good, elsewhere).find("starts 0.4 m from the robot (tolerance 0.3 m)"), std::string::npos)
      << rejected(good, elsewhere);
  elsewhere = robot;
  elsewhere.state.yaw_rad -= 0.35;
  EXPECT_NE(rejected(good, elsewhere).find("rad of yaw"), std::string::npos);
  elsewhere = robot;
  elsewhere.state.q_rad[6] += 0.5;
  EXPECT_NE(rejected(good, elsewhere).find("a joint 0.5 rad"), std::string::npos);
  EXPECT_NE(follower.Accept(good, At(2.5), robot).find("before it arrived"), std::string::npos);
  msg = good;
  msg.start_utime = INT64_MAX;
  EXPECT_NE(rejected(msg).find("from the sim's time"), std::string::npos);
  msg = good;
  for (double& d : msg.durations_s) d *= 1e7;  // (coefficients unchanged: also no MINCO solution)
  EXPECT_FALSE(rejected(msg).empty());
  EXPECT_EQ(follower.counts().rejected, 11);
  EXPECT_EQ(follower.counts().accepted, 0);
  // Nothing to follow: held.
  ExpectAtRestAt(follower.StateAt(At(1.0), robot), robot);
  // A yaw a whole turn away is the same heading.
  elsewhere = robot;
  elsewhere.state.yaw_rad += 2.0 * M_PI;
  EXPECT_EQ(rejected(good, elsewhere), "");
}

TEST(TrajectoryFollower, ANewTrajectoryTakesOverAtItsStartFromWhereTheOldOnePutsTheRobot) {
  TrajectoryFollower follower(kJoints, {});
  sim::PlantState state = Robot();
  ASSERT_EQ(follower.Accept(MessageFrom(state, kStart, 1), At(0.0), state), "");
  for (double t = 0.0; t <= 0.8; t += 0.01) state = follower.StateAt(At(t), state);
  // Replanned from where the first puts the robot at t = 1.0 s (not from where it is now).
  const ArcYawTrajectory first = TrajectoryFrom(Robot());
  TrajectorySample point = first.MakePoint();
  first.Evaluate(1.0, &point);
  sim::PlantState at_1s = Robot();
  at_1s.state = point.state;
  ASSERT_EQ(follower.Accept(MessageFrom(at_1s, At(1.0), 2), At(0.8), state), "");
  // Not where the robot is now: the start is checked against where the first puts it then.
  EXPECT_GT(std::hypot(at_1s.state.x_m - state.state.x_m, at_1s.state.y_m - state.state.y_m), 0.0);
  state = follower.StateAt(At(0.9), state);
  EXPECT_EQ(follower.active_id(), 1);
  EXPECT_GT(state.v_mps, 0.1);  // still on the first
  state = follower.StateAt(At(1.0), state);
  EXPECT_EQ(follower.active_id(), 2);
  EXPECT_NEAR(state.state.x_m, at_1s.state.x_m, 1e-12);
  EXPECT_EQ(state.v_mps, 0.0);  // the second starts from rest
  EXPECT_EQ(follower.counts().started, 2);
}

}  // namespace
}  // namespace topay::simproc
