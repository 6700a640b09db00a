#include "procs/planner/active_trajectory.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "tests/core/trajectory/straight_drive.h"

namespace topay::planner {
namespace {

// 4 m along +x in 8 s from (1, 2), joints (2 of them) from 0 to 0.4 rad.
ActiveTrajectory Drive() {
  ActiveTrajectory active;
  active.trajectory_id = 3;
  active.start_utime = 1'000'000;
  active.trajectory = test::StraightDrive();
  return active;
}

TEST(ActiveTrajectoryTest, SamplesAreClampedToTheTrajectory) {
  const ActiveTrajectory a = Drive();
  EXPECT_EQ(a.end_utime(), 9'000'000);
  EXPECT_TRUE(a.EndedBy(9'000'000));
  EXPECT_FALSE(a.EndedBy(8'999'999));
  const TrajectorySample before = a.SampleAt(0);
  EXPECT_NEAR(before.state.x_m, 1.0, 1e-12);
  EXPECT_EQ(before.v_mps, 0.0);
  const TrajectorySample mid = a.SampleAt(5'000'000);
  EXPECT_NEAR(mid.state.x_m, 3.0, 1e-6);  // symmetric rest-to-rest profile: half way at half time
  EXPECT_GT(mid.v_mps, 0.3);
  const TrajectorySample after = a.SampleAt(20'000'000);
  EXPECT_NEAR(after.state.x_m, 5.0, 1e-6);
  EXPECT_NEAR(after.state.q_rad(1), 0.4, 1e-9);
}

// The demo's case: a replan (7) published to start at 2.0 s while a stop (6, from 1.0 s) runs:
// until 2.0 s the robot is on the stop, and a safe stop or replan asked for before then must
// start from the stop, not from the start of the replan that has not begun.
TEST(ActiveTrajectoryTest, TheRobotIsOnTheNewestTrajectoryThatHasStarted) {
  std::deque<ActiveTrajectory> replaced;
  ActiveTrajectory first = Drive();  // id 3, from 1.0 s
  ActiveTrajectory stop = Drive();
  stop.trajectory_id = 6;
  stop.start_utime = 1'500'000;
  stop.stopping = true;
  replaced.push_back(first);
  replaced.push_back(stop);
  ActiveTrajectory replan = Drive();
  replan.trajectory_id = 7;
  replan.start_utime = 2'000'000;
  EXPECT_EQ(TrajectoryOnAt(&replan, replaced, 900'000), nullptr);
  EXPECT_EQ(TrajectoryOnAt(&replan, replaced, 1'000'000)->trajectory_id, 3);
  EXPECT_EQ(TrajectoryOnAt(&replan, replaced, 1'700'000)->trajectory_id, 6);
  EXPECT_EQ(TrajectoryOnAt(&replan, replaced, 1'999'999)->trajectory_id, 6);
  EXPECT_EQ(TrajectoryOnAt(&replan, replaced, 2'000'000)->trajectory_id, 7);
  EXPECT_EQ(TrajectoryOnAt(nullptr, replaced, 5'000'000)->trajectory_id, 6);
  EXPECT_EQ(TrajectoryOnAt(nullptr, {}, 5'000'000), nullptr);
}

TEST(ActiveTrajectoryTest, DriftIsMeasuredAtTheStatesTime) {
  const ActiveTrajectory a = Drive();
  msgs::RobotStateEstimate robot;
  robot.utime = 5'000'000;
  robot.state = a.SampleAt(robot.utime).state;
  EXPECT_NEAR(MeasureDrift(a, robot).position_m, 0.0, 1e-12);
  robot.state.y_m += 0.3;
  robot.state.yaw_rad += 2 * M_PI + 0.1;  // wrapped
  robot.state.q_rad(0) -= 0.2;
  const Drift d = MeasureDrift(a, robot);
  EXPECT_NEAR(d.position_m, 0.3, 1e-9);
  EXPECT_NEAR(d.yaw_rad, 0.1, 1e-9);
  EXPECT_NEAR(d.joint_rad, 0.2, 1e-9);
}

// A robot 0.2 m left of the straight trajectory and 0.1 rad / 0.05 rad (joint 1) off keeps that
// error: it is where the trajectory will be at t0, plus the error, with the trajectory's rates.
TEST(ActiveTrajectoryTest, ADriftedStartIsTheTrajectoryAtT0WithTheRobotsError) {
  const ActiveTrajectory a = Drive();
  msgs::RobotStateEstimate robot;
  robot.utime = 3'000'000;
  const TrajectorySample now = a.SampleAt(robot.utime);
  robot.state = now.state;
  robot.state.y_m += 0.2;
  robot.state.yaw_rad += 0.1;
  robot.state.q_rad(1) += 0.05;
  robot.v_mps = 3.0;  // measured rates play no part (a constant-rate extrapolation would)
  const std::int64_t t0 = 4'000'000;
  const TrajectorySample at_t0 = a.SampleAt(t0);
  const TrajectorySample start = PredictDriftedStart(a, robot, t0);
  EXPECT_NEAR(start.state.x_m, at_t0.state.x_m, 1e-9);
  EXPECT_NEAR(start.state.y_m, at_t0.state.y_m + 0.2, 1e-9);
  EXPECT_NEAR(start.state.yaw_rad, at_t0.state.yaw_rad + 0.1, 1e-9);
  EXPECT_NEAR(start.state.q_rad(0), at_t0.state.q_rad(0), 1e-9);
  EXPECT_NEAR(start.state.q_rad(1), at_t0.state.q_rad(1) + 0.05, 1e-9);
  EXPECT_NEAR(start.v_mps, at_t0.v_mps, 1e-12);
  EXPECT_NEAR(start.a_mps2, at_t0.a_mps2, 1e-12);
  EXPECT_NEAR(start.qd_radps(1), at_t0.qd_radps(1), 1e-12);
}

// On a turning trajectory the base offset turns with it: a robot 0.1 m outside a quarter turn
// in place is 0.1 m outside it a quarter turn later, in the rotated direction.
TEST(ActiveTrajectoryTest, ADriftedStartTurnsItsOffsetWithTheTrajectory) {
  auto t = std::make_shared<ArcYawTrajectory>(2, 2, ArcYawTrajectory::Options{});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(4, 3), tail = Eigen::MatrixXd::Zero(4, 3);
  tail(1, 0) = std::numbers::pi / 2;  // yaw 0 -> pi/2 in place
  Eigen::MatrixXd waypoints(4, 1);
  waypoints << 0.0, std::numbers::pi / 4, 0.0, 0.0;
  t->Update({0.0, 0.0}, head, tail, waypoints, Eigen::VectorXd::Constant(2, 2.0));
  ActiveTrajectory a;
  a.trajectory_id = 1;
  a.start_utime = 0;
  a.trajectory = t;
  msgs::RobotStateEstimate robot;
  robot.utime = 0;
  robot.state = a.SampleAt(0).state;
  robot.state.x_m += 0.1;  // 0.1 m ahead along the initial heading
  const TrajectorySample start = PredictDriftedStart(a, robot, 4'000'000);  // the end: yaw pi/2
  EXPECT_NEAR(start.state.yaw_rad, std::numbers::pi / 2, 1e-6);
  EXPECT_NEAR(start.state.x_m, 0.0, 1e-6);
  EXPECT_NEAR(start.state.y_m, 0.1, 1e-6);
}

// Limits for Drive()'s 2 joints: the robot's (config/robot/topay_mm.yaml), and the plans' with
// 85 % of its accelerations.
TrackerLimits TwoJointLimits(double acceleration_share) {
  TrackerLimits limits;
  limits.base = BaseLimits{1.0, 0.8 * acceleration_share, 0.9, 1.0 * acceleration_share};
  limits.qd_max_radps = Eigen::VectorXd::Constant(2, 2.35);
  limits.qdd_max_radps2 = Eigen::VectorXd::Constant(2, 6.28 * acceleration_share);
  return limits;
}

// A robot 0.2 m left of the straight trajectory, turned 0.15 rad towards it, at the trajectory's
// speed: in the second to t0 the tracker brings it back towards the line (0.05 m across it then,
// 0.1 m ahead), so the tracked start is nearer the trajectory than the carried one (0.2 m off),
// still on the robot's side, and moving; its accelerations within the plans' limits.
TEST(ActiveTrajectoryTest, ATrackedStartIsWhereTheTrackerBringsTheRobot) {
  const ActiveTrajectory a = Drive();
  msgs::RobotStateEstimate robot;
  robot.utime = 3'000'000;
  const TrajectorySample now = a.SampleAt(robot.utime);
  robot.state = now.state;
  robot.state.y_m += 0.2;
  robot.state.yaw_rad -= 0.15;
  robot.v_mps = now.v_mps;  // no joint rates: taken as 0
  const std::int64_t t0 = 4'000'000;
  const TrajectorySample at_t0 = a.SampleAt(t0);
  const TrackerLimits plan_limits = TwoJointLimits(0.85);
  TrackedRobotPredictor predictor(NmpcOptions{}, TwoJointLimits(1.0));
  TrackedRobotPredictionSummary summary;
  const TrajectorySample start = PredictTrackedStart(&predictor, a, robot, t0, plan_limits, &summary);
  const TrajectorySample carried = PredictDriftedStart(a, robot, t0);
  EXPECT_NEAR(carried.state.y_m - at_t0.state.y_m, 0.2, 1e-9);
  EXPECT_GT(start.state.y_m - at_t0.state.y_m, 0.0);
  EXPECT_LT(start.state.y_m - at_t0.state.y_m, 0.1);
  std::printf("[ figure ] tracked start: %.3f m along, %.3f m across the trajectory at t0, yaw %.3f rad off, v %.3f m/s (trajectory %.3f m/s)\n", start.state.x_m - at_t0.state.x_m, start.state.y_m - at_t0.state.y_m, start.state.yaw_rad - at_t0.state.yaw_rad, start.v_mps, at_t0.v_mps);
  EXPECT_LT(std::hypot(start.state.x_m - at_t0.state.x_m, start.state.y_m - at_t0.state.y_m), 0.15);
  EXPECT_GT(start.v_mps, 0.5 * at_t0.v_mps);
  EXPECT_EQ(summary.cycles, 50);
  EXPECT_LE(std::abs(start.a_mps2), plan_limits.base.a_max_mps2);
  EXPECT_LE(std::abs(start.beta_radps2), plan_limits.base.beta_max_radps2);
  EXPECT_LE(start.qdd_radps2.cwiseAbs().maxCoeff(), plan_limits.qdd_max_radps2(0));
  // A robot with the wrong joint count is refused by name, not predicted.
  robot.state.q_rad.resize(3);
  EXPECT_THROW(PredictTrackedStart(&predictor, a, robot, t0, plan_limits), std::invalid_argument);
}

TEST(ActiveTrajectoryTest, SweptRegionHoldsTheBaseGrownByTheReach) {
  const ActiveTrajectory a = Drive();
  const Eigen::AlignedBox3d r = SweptRegion(*a.trajectory, 4.0, 100.0, 1.0, 1.6);
  EXPECT_NEAR(r.min().x(), 3.0 - 1.1, 1e-6);
  EXPECT_NEAR(r.max().x(), 5.0 + 1.1, 1e-6);
  EXPECT_NEAR(r.min().y(), 2.0 - 1.1, 1e-9);
  EXPECT_NEAR(r.max().z(), 1.6, 1e-12);
}

}  // namespace
}  // namespace topay::planner
