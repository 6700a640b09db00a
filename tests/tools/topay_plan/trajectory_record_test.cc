#include "tools/topay_plan/trajectory_record.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace topay::plan {
namespace {

// A 3-piece trajectory with 2 joints from fixed, non-trivial boundary data.
ArcYawTrajectory MakeTrajectory(const Eigen::Vector3d& durations_s) {
  ArcYawTrajectory trajectory(2, 3, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(4, 3);
  head.col(0) << 0.0, 0.3, 0.1, -0.2;
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(4, 3);
  tail.col(0) << 4.0, 1.1, 0.7, 0.5;
  Eigen::MatrixXd waypoints(4, 2);
  waypoints << 1.0, 2.6,  //
      0.5, 0.9,           //
      0.2, 0.5,           //
      -0.1, 0.3;
  trajectory.Update(Eigen::Vector2d(1.5, -2.0), head, tail, waypoints, durations_s);
  return trajectory;
}

TEST(TrajectoryRecordTest, SamplesAreAtMultiplesOfThePeriodPlusTheExactEnd) {
  const ArcYawTrajectory trajectory = MakeTrajectory({1.2, 0.9, 1.345});
  const std::vector<TrajectorySample> samples = SampleTrajectory(trajectory, 0.01);
  ASSERT_EQ(samples.size(), 346u);  // 0, 0.01, .., 3.44, then 3.445
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
    ASSERT_EQ(samples[i].t_s, static_cast<double>(i) * 0.01) << i;
  }
  EXPECT_EQ(samples.back().t_s, trajectory.duration_s());
  TrajectorySample point = trajectory.MakePoint();
  for (std::size_t i : {std::size_t{0}, std::size_t{123}, samples.size() - 1}) {
    trajectory.Evaluate(samples[i].t_s, &point);
    EXPECT_EQ(samples[i].state.x_m, point.state.x_m);
    EXPECT_EQ(samples[i].state.y_m, point.state.y_m);
    EXPECT_EQ(samples[i].state.yaw_rad, point.state.yaw_rad);
    EXPECT_EQ(samples[i].s_m, point.s_m);
    EXPECT_EQ(samples[i].v_mps, point.v_mps);
    EXPECT_EQ(samples[i].omega_radps, point.omega_radps);
    EXPECT_EQ(samples[i].a_mps2, point.a_mps2);
    EXPECT_EQ(samples[i].beta_radps2, point.beta_radps2);
    EXPECT_EQ(samples[i].state.q_rad, point.state.q_rad);
  }
  // A duration that is a whole number of periods gives no duplicate end sample.
  const std::vector<TrajectorySample> whole = SampleTrajectory(MakeTrajectory({1.0, 0.5, 0.5}));
  ASSERT_EQ(whole.size(), 201u);
  EXPECT_NEAR(whole.back().t_s, 2.0, 1e-12);
  EXPECT_GT(whole.back().t_s - whole[whole.size() - 2].t_s, 0.0099);
  EXPECT_THROW(SampleTrajectory(trajectory, 0.0), std::invalid_argument);
  EXPECT_THROW(SampleTrajectory(ArcYawTrajectory(2, 3, {})), std::invalid_argument);
}

TEST(TrajectoryRecordTest, PiecesRebuildTheSameTrajectory) {
  const ArcYawTrajectory trajectory = MakeTrajectory({1.2, 0.9, 1.345});
  const TrajectoryPieces pieces = PiecesOf(trajectory);
  EXPECT_EQ(pieces.coefficients.rows(), 18);
  EXPECT_EQ(pieces.coefficients.cols(), 4);
  EXPECT_EQ(pieces.durations_s, Eigen::Vector3d(1.2, 0.9, 1.345));
  EXPECT_EQ(pieces.p0_W_m, Eigen::Vector2d(1.5, -2.0));
  EXPECT_EQ(pieces.panels_per_piece, 12);
  const ArcYawTrajectory rebuilt = RebuildTrajectory(pieces);
  EXPECT_LT((rebuilt.minco().coefficients() - pieces.coefficients).cwiseAbs().maxCoeff(), 1e-9);
  TrajectorySample a = trajectory.MakePoint(), b = rebuilt.MakePoint();
  for (double t_s : {0.0, 0.7, 1.2, 2.5, 3.445}) {
    trajectory.Evaluate(t_s, &a);
    rebuilt.Evaluate(t_s, &b);
    EXPECT_NEAR(a.state.x_m, b.state.x_m, 1e-9) << t_s;
    EXPECT_NEAR(a.state.y_m, b.state.y_m, 1e-9) << t_s;
    EXPECT_LT((a.state.q_rad - b.state.q_rad).cwiseAbs().maxCoeff(), 1e-9) << t_s;
    EXPECT_NEAR(a.omega_radps, b.omega_radps, 1e-9) << t_s;
  }
}

TEST(TrajectoryRecordTest, PiecesThatAreNotAMincoTrajectoryAreRejected) {
  const TrajectoryPieces good = PiecesOf(MakeTrajectory({1.2, 0.9, 1.345}));
  TrajectoryPieces kinked = good;
  kinked.coefficients(6 + 3, 2) += 0.01;  // piece 1's t^3 of q1: jerk jumps at the joints
  EXPECT_THROW(RebuildTrajectory(kinked), std::invalid_argument);
  TrajectoryPieces short_rows = good;
  short_rows.coefficients.conservativeResize(17, 4);
  EXPECT_THROW(RebuildTrajectory(short_rows), std::invalid_argument);
  TrajectoryPieces nan = good;
  nan.p0_W_m.x() = std::nan("");
  EXPECT_THROW(RebuildTrajectory(nan), std::invalid_argument);
  TrajectoryPieces zero_duration = good;
  zero_duration.durations_s(1) = 0.0;
  EXPECT_THROW(RebuildTrajectory(zero_duration), std::invalid_argument);
}

TEST(TrajectoryRecordTest, FiguresCopyTheValidationReport) {
  ValidationReport report;
  report.ok = true;
  report.duration_s = 12.5;
  report.num_samples = 1251;
  report.min_obstacle.clearance_m = 0.042;
  report.min_obstacle.name = "sphere 5 (link4)";
  report.min_self.clearance_m = 0.11;
  report.worst_limit.ratio = 0.97;
  report.worst_limit.limit = Limit::kJointVelocity;
  report.worst_limit.joint = 2;
  report.worst_limit.t_s = 3.21;
  report.end_position_error_m = 0.003;
  report.end_orientation_error_rad = 0.004;
  const TrajectoryValidationFigures f = FiguresOf(report);
  EXPECT_TRUE(f.ok);
  EXPECT_EQ(f.duration_s, 12.5);
  EXPECT_EQ(f.num_samples, 1251);
  EXPECT_EQ(f.min_clearance_m, 0.042);
  EXPECT_EQ(f.min_clearance_part, "sphere 5 (link4)");
  EXPECT_EQ(f.min_self_clearance_m, 0.11);
  EXPECT_EQ(f.worst_limit_ratio, 0.97);
  EXPECT_EQ(f.worst_limit, "joint velocity (joint 3)");
  EXPECT_EQ(f.worst_limit_t_s, 3.21);
  EXPECT_EQ(f.end_position_error_m, 0.003);
  EXPECT_EQ(f.end_orientation_error_rad, 0.004);
  report.worst_limit.limit = Limit::kYawRate;
  report.worst_limit.joint = -1;
  EXPECT_EQ(FiguresOf(report).worst_limit, "yaw rate");
}

}  // namespace
}  // namespace topay::plan
