#include "core/planner/stopping_trajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/common/expect_same_motion.h"

#include "core/io/robot_loader.h"
#include "core/trajectory/arc_yaw_state_at.h"
#include "core/validate/limit_ratios.h"

namespace topay {
namespace {

constexpr int kJoints = 7;

// Checks of a stopping trajectory against the current one it leaves at t0: C2 at the join,
// within the limits (the validator's WorstRateRatio, 1 % as the validator allows), at rest
// at the end, and its base within path_tolerance_m of the current path (densely sampled
// from t0 on).
void ExpectStopsOnThePath(const ArcYawTrajectory& current, double t0,
                          const StoppingTrajectory& stop, const BaseLimits& base,
                          const JointLimits& joints, double path_tolerance_m = 0.003) {
  ASSERT_TRUE(stop.success()) << stop.reason;
  const ArcYawTrajectory& s = *stop.trajectory;
  EXPECT_EQ(s.num_joints(), current.num_joints());
  TrajectorySample a = current.MakePoint(), b = s.MakePoint();
  current.Evaluate(t0, &a);
  s.Evaluate(0.0, &b);
  testing::ExpectSameMotion(a, b, 1e-9, 1e-9);
  // At rest at the end.
  s.Evaluate(s.duration_s(), &b);
  EXPECT_NEAR(b.v_mps, 0.0, 1e-9);
  EXPECT_NEAR(b.omega_radps, 0.0, 1e-9);
  EXPECT_NEAR(b.a_mps2, 0.0, 1e-9);
  EXPECT_LT(b.qd_radps.cwiseAbs().maxCoeff(), 1e-9);
  // Within the limits every 5 ms, and on the current path.
  std::vector<Eigen::Vector2d> path;
  for (double t = t0; t <= current.duration_s() + 1e-12; t += 0.001) {
    current.Evaluate(t, &a);
    path.emplace_back(a.state.x_m, a.state.y_m);
  }
  double worst_ratio = 0.0, worst_distance = 0.0;
  for (double t = 0.0; t <= s.duration_s(); t += 0.005) {
    s.Evaluate(t, &b);
    worst_ratio = std::max(worst_ratio, WorstRateRatio(b, base, joints).ratio);
    int joint = -1;
    EXPECT_LE(MaxJointPositionExcess(b.state.q_rad, joints, &joint), 1e-9);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& p : path) {
      nearest = std::min(nearest, std::hypot(p.x() - b.state.x_m, p.y() - b.state.y_m));
    }
    worst_distance = std::max(worst_distance, nearest);
  }
  EXPECT_LE(worst_ratio, 1.01);
  EXPECT_LE(worst_distance, path_tolerance_m);
  EXPECT_LE(stop.max_path_deviation_m, path_tolerance_m);
  ::testing::Test::RecordProperty("worst_distance_m", std::to_string(worst_distance));
}

class StoppingTrajectoryTest : public ::testing::Test {
 protected:
  StoppingTrajectoryTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        current_(kJoints, 3, {}) {
    // A 4.5 m drive turning 0.8 rad in 9 s, joints 2 and 4 moving 0.5 rad, from rest to rest.
    Eigen::MatrixXd head = Eigen::MatrixXd::Zero(kJoints + 2, 3), tail = head;
    head(1, 0) = 0.2;
    head.col(0).tail(kJoints) << 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1;
    tail.col(0) = head.col(0);
    tail(0, 0) = 4.5;
    tail(1, 0) = 1.0;
    tail(3, 0) = 1.3;
    tail(5, 0) = 0.7;
    Eigen::MatrixXd waypoints(kJoints + 2, 2);
    waypoints.col(0) = head.col(0) + 0.25 * (tail.col(0) - head.col(0));
    waypoints.col(1) = head.col(0) + 0.75 * (tail.col(0) - head.col(0));
    current_.Update(Eigen::Vector2d(1.0, -2.0), head, tail, waypoints,
                    Eigen::VectorXd::Constant(3, 3.0));
  }

  RobotModel model_;
  BaseLimits base_;
  ArcYawTrajectory current_;
};

TEST_F(StoppingTrajectoryTest, TheCurrentTrajectoryIsWithinTheLimits) {
  // The premise of the tests below.
  TrajectorySample sample = current_.MakePoint();
  double worst = 0.0;
  for (double t = 0.0; t <= current_.duration_s(); t += 0.01) {
    current_.Evaluate(t, &sample);
    worst = std::max(worst, WorstRateRatio(sample, base_, model_.joint_limits).ratio);
  }
  EXPECT_LE(worst, 1.0);
  EXPECT_GT(worst, 0.5);  // and not trivially slow
}

TEST_F(StoppingTrajectoryTest, StopsC2WithinLimitsOnThePathFromAnyTime) {
  for (double t0 : {0.0, 0.7, 2.0, 3.3, 4.5, 5.9}) {
    SCOPED_TRACE(t0);
    const StoppingTrajectory stop =
        MakeStoppingTrajectory(current_, t0, base_, model_.joint_limits);
    ExpectStopsOnThePath(current_, t0, stop, base_, model_.joint_limits);
    EXPECT_FALSE(stop.follows_to_end);
    // It stops before the current trajectory would.
    EXPECT_LT(t0 + stop.path_time_used_s, current_.duration_s());
    EXPECT_NEAR(stop.path_time_used_s, 0.5 * stop.duration_s, 1e-9);
  }
}

TEST_F(StoppingTrajectoryTest, NearTheEndItFollowsTheCurrentTrajectoryToItsEnd) {
  const double t0 = current_.duration_s() - 0.1;  // T / 2 >= 0.15 s: beyond the end
  const StoppingTrajectory stop = MakeStoppingTrajectory(current_, t0, base_, model_.joint_limits);
  ExpectStopsOnThePath(current_, t0, stop, base_, model_.joint_limits);
  EXPECT_TRUE(stop.follows_to_end);
  TrajectorySample end = current_.MakePoint(), stop_end = current_.MakePoint();
  current_.Evaluate(current_.duration_s(), &end);
  stop.trajectory->Evaluate(stop.duration_s, &stop_end);
  EXPECT_NEAR(stop_end.state.x_m, end.state.x_m, 1e-3);
  EXPECT_NEAR(stop_end.state.y_m, end.state.y_m, 1e-3);
}

TEST_F(StoppingTrajectoryTest, TightLimitsLengthenIt) {
  // Half the acceleration limits: the first duration (3 v / a) is tried, found beyond them or
  // not, and in the end the result is within the tighter limits.
  BaseLimits tight = base_;
  tight.a_max_mps2 = 0.3;
  tight.beta_max_radps2 = 0.3;
  StoppingTrajectoryOptions options;
  options.duration_per_rate_ratio = 0.5;  // too short at first: must be lengthened
  const double t0 = 4.5;
  const StoppingTrajectory stop =
      MakeStoppingTrajectory(current_, t0, tight, model_.joint_limits, options);
  ExpectStopsOnThePath(current_, t0, stop, tight, model_.joint_limits);
  EXPECT_GT(stop.attempts, 1);
}

TEST_F(StoppingTrajectoryTest, ImpossibleOrBadInputGivesAReason) {
  StoppingTrajectoryOptions options;
  options.max_attempts = 1;
  options.duration_per_rate_ratio = 0.1;
  options.min_duration_s = 0.05;
  const StoppingTrajectory stop =
      MakeStoppingTrajectory(current_, 4.5, base_, model_.joint_limits, options);
  EXPECT_FALSE(stop.success());
  EXPECT_NE(stop.reason.find("within the limits"), std::string::npos) << stop.reason;
  EXPECT_GT(stop.worst_limit_ratio, 1.01);
  EXPECT_FALSE(MakeStoppingTrajectory(current_, std::nan(""), base_, model_.joint_limits).success());
  const ArcYawTrajectory unsolved(kJoints, 2, {});
  EXPECT_FALSE(MakeStoppingTrajectory(unsolved, 0.0, base_, model_.joint_limits).success());
  options = StoppingTrajectoryOptions();
  options.lengthen_factor = 1.0;
  EXPECT_THROW(MakeStoppingTrajectory(current_, 1.0, base_, model_.joint_limits, options),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
