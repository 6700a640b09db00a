#include "core/trajectory/offset_trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace topay {
namespace {

// 3 m in 6 s from (1, 2), turning from yaw 0.2 to 1.4 rad, two joints from (0, 0.5) to (0.3, 0.1).
ArcYawTrajectory TurningDrive() {
  ArcYawTrajectory t(2, 3, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(4, 3), tail = Eigen::MatrixXd::Zero(4, 3);
  head.col(0) << 0.0, 0.2, 0.0, 0.5;
  tail.col(0) << 3.0, 1.4, 0.3, 0.1;
  Eigen::MatrixXd waypoints(4, 2);
  waypoints << 0.8, 2.2, 0.4, 1.1, 0.1, 0.2, 0.4, 0.2;
  t.Update({1.0, 2.0}, head, tail, waypoints, Eigen::VectorXd::Constant(3, 2.0));
  return t;
}

TEST(OffsetTrajectoryTest, NoOffsetGivesTheSameTrajectory) {
  const ArcYawTrajectory t = TurningDrive();
  const ArcYawTrajectory same = OffsetTrajectory(t, {1.0, 2.0}, 0.0, Eigen::VectorXd::Zero(2));
  TrajectorySample a = t.MakePoint(), b = same.MakePoint();
  for (int k = 0; k <= 60; ++k) {
    t.Evaluate(0.1 * k, &a);
    same.Evaluate(0.1 * k, &b);
    EXPECT_NEAR(b.state.x_m, a.state.x_m, 1e-9) << k;
    EXPECT_NEAR(b.state.y_m, a.state.y_m, 1e-9) << k;
    EXPECT_NEAR(b.state.yaw_rad, a.state.yaw_rad, 1e-9) << k;
    EXPECT_NEAR((b.state.q_rad - a.state.q_rad).cwiseAbs().maxCoeff(), 0.0, 1e-9) << k;
    EXPECT_NEAR(b.v_mps, a.v_mps, 1e-9) << k;
    EXPECT_NEAR(b.beta_radps2, a.beta_radps2, 1e-8) << k;
  }
}

// Moved to (-1, 0.5), turned by 0.3 rad, the joints +0.1 and -0.2: at every time the yaw and
// joints are the original's plus the offsets, the rates the original's, and the base where the
// original's path, turned by 0.3 rad about its start, puts it.
TEST(OffsetTrajectoryTest, TheMotionIsMovedTurnedAndOffsetRigidly) {
  const ArcYawTrajectory t = TurningDrive();
  const Eigen::Vector2d p0(-1.0, 0.5);
  const double turn = 0.3;
  const Eigen::Vector2d dq(0.1, -0.2);
  const ArcYawTrajectory moved = OffsetTrajectory(t, p0, turn, dq);
  EXPECT_DOUBLE_EQ(moved.duration_s(), t.duration_s());
  const Eigen::Rotation2Dd rotate(turn);
  TrajectorySample a = t.MakePoint(), b = moved.MakePoint();
  for (int k = 0; k <= 60; ++k) {
    t.Evaluate(0.1 * k, &a);
    moved.Evaluate(0.1 * k, &b);
    const Eigen::Vector2d expected = p0 + rotate * (Eigen::Vector2d(a.state.x_m, a.state.y_m) - Eigen::Vector2d(1.0, 2.0));
    EXPECT_NEAR(b.state.x_m, expected.x(), 1e-9) << k;
    EXPECT_NEAR(b.state.y_m, expected.y(), 1e-9) << k;
    EXPECT_NEAR(b.state.yaw_rad, a.state.yaw_rad + turn, 1e-9) << k;
    EXPECT_NEAR((b.state.q_rad - a.state.q_rad - dq).cwiseAbs().maxCoeff(), 0.0, 1e-9) << k;
    EXPECT_NEAR(b.s_m, a.s_m, 1e-9) << k;
    EXPECT_NEAR(b.omega_radps, a.omega_radps, 1e-9) << k;
    EXPECT_NEAR((b.qd_radps - a.qd_radps).cwiseAbs().maxCoeff(), 0.0, 1e-9) << k;
  }
}

TEST(OffsetTrajectoryTest, BadOffsetsAreRefused) {
  const ArcYawTrajectory t = TurningDrive();
  EXPECT_THROW(OffsetTrajectory(t, {0.0, 0.0}, 0.0, Eigen::VectorXd::Zero(3)), std::invalid_argument);
  EXPECT_THROW(OffsetTrajectory(t, {0.0, 0.0}, std::nan(""), Eigen::VectorXd::Zero(2)), std::invalid_argument);
  EXPECT_THROW(OffsetTrajectory(t, {INFINITY, 0.0}, 0.0, Eigen::VectorXd::Zero(2)), std::invalid_argument);
  const ArcYawTrajectory never(2, 3, {});
  EXPECT_THROW(OffsetTrajectory(never, {0.0, 0.0}, 0.0, Eigen::VectorXd::Zero(2)), std::invalid_argument);
}

}  // namespace
}  // namespace topay
