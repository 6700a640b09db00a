// The estimator: waits for its first pose; converges from a wrong initial pose (an honest
// covariance: by the updates; an over-confident one: by the re-initialisation after
// reinit_after_rejections gated poses); delayed poses give exactly the in-order result; the gate
// rejects an outlier jump; bad input (NaN, dt <= 0, out of order, too old) is counted and changes
// nothing; the prediction to a later time uses the latest odometry.

#include "core/estimation/se2_estimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/common/angles.h"
#include "core/estimation/pose_update.h"
#include "estimator_test_drive.h"

namespace topay {
namespace {

using test::Drive;
using test::DriveOptions;
using test::kT0Us;

double PositionError(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).head<2>().norm(); }
double YawError(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return std::abs(WrapAngle(a.z() - b.z())); }

// Feeds every input in arrival order: odometry at its stamp, a pose at its stamp + delay (at
// equal arrival times odometry first). `on_pose` is called after each pose.
template <class OnPose>
void Feed(const Drive& d, std::int64_t pose_delay_us, Se2Estimator* e, OnPose on_pose) {
  std::size_t i = 0, j = 0;
  while (i < d.odometry.size() || j < d.poses.size()) {
    const bool odometry_next =
        j == d.poses.size() || (i < d.odometry.size() && d.odometry[i].t_us <= d.poses[j].t_us + pose_delay_us);
    if (odometry_next) {
      e->AddOdometry(d.odometry[i].t_us, d.odometry[i].v_mps, d.odometry[i].omega_radps);
      ++i;
    } else {
      e->AddPose(d.poses[j].t_us, d.poses[j].z_WB);
      on_pose(d.poses[j]);
      ++j;
    }
  }
}
void Feed(const Drive& d, std::int64_t pose_delay_us, Se2Estimator* e) {
  Feed(d, pose_delay_us, e, [](const test::PoseSample&) {});
}

DriveOptions NoisyPoses() {
  DriveOptions o;
  o.pose_xy_stddev_m = 0.03;
  o.pose_yaw_stddev_rad = 0.02;
  o.slip_stddev = 0.02;
  o.omega_period_s = 6.0;
  return o;
}

TEST(Se2Estimator, WaitsForTheFirstPose) {
  Se2Estimator e{EstimatorOptions{}};
  PoseEstimate estimate;
  EXPECT_EQ(e.AddOdometry(kT0Us, 1.0, 0.0), EstimatorInput::kApplied);
  EXPECT_FALSE(e.initialised());
  EXPECT_FALSE(e.EstimateAt(kT0Us + 10'000, &estimate));
  EXPECT_EQ(e.AddPose(kT0Us + 20'000, Eigen::Vector3d(1.0, 2.0, 0.5)), EstimatorInput::kApplied);
  EXPECT_EQ(e.last_pose_outcome(), PoseOutcome::kInitialised);
  ASSERT_TRUE(e.EstimateAt(kT0Us + 20'000, &estimate));
  EXPECT_EQ(estimate.X_WB, Eigen::Vector3d(1.0, 2.0, 0.5));
  EXPECT_EQ(estimate.P_WB, PoseMeasurementNoise(e.options()));
}

TEST(Se2Estimator, EstimateAtPredictsWithTheLatestOdometry) {
  Se2Estimator e{EstimatorOptions{}};
  e.AddPose(kT0Us, Eigen::Vector3d(0.0, 0.0, 0.0));
  e.AddOdometry(kT0Us + 1000, 1.0, 0.0);
  PoseEstimate estimate;
  ASSERT_TRUE(e.EstimateAt(kT0Us + 101'000, &estimate));
  EXPECT_NEAR(estimate.X_WB.x(), 0.1, 1e-12);
  EXPECT_EQ(estimate.t_us, kT0Us + 101'000);
  EXPECT_GT(estimate.P_WB(0, 0), e.Newest().P_WB(0, 0));  // the prediction adds noise
  // Not moved back before the newest event.
  ASSERT_TRUE(e.EstimateAt(kT0Us, &estimate));
  EXPECT_EQ(estimate.t_us, kT0Us + 1000);
}

// Converges from 1 m and 0.5 rad off when its covariance says it may be that far off: the
// first pose already moves it most of the way (K ~ 1); within 1 s (10 poses) it is within 5 cm.
TEST(Se2Estimator, ConvergesFromAWrongInitialPoseWithAnHonestCovariance) {
  const Drive d = test::SimulateDrive(NoisyPoses(), Eigen::Vector3d(0.0, 0.0, 0.0));
  Se2Estimator e{EstimatorOptions{}};
  e.Reset(kT0Us - 1000, Eigen::Vector3d(1.0, 0.0, 0.5), Eigen::Vector3d(1.0, 1.0, 0.25).asDiagonal());
  double worst_after_1s = 0.0, worst_yaw_after_1s = 0.0;
  Feed(d, 0, &e, [&](const test::PoseSample& p) {
    if (p.t_us < kT0Us + 1'000'000) return;
    worst_after_1s = std::max(worst_after_1s, PositionError(e.Newest().X_WB, p.truth_WB));
    worst_yaw_after_1s = std::max(worst_yaw_after_1s, YawError(e.Newest().X_WB, p.truth_WB));
  });
  std::printf("honest start: worst after 1 s %.4f m, %.4f rad\n", worst_after_1s, worst_yaw_after_1s);
  EXPECT_LT(worst_after_1s, 0.05);
  EXPECT_LT(worst_yaw_after_1s, 0.03);
  EXPECT_LE(e.summary().poses_gated, 2);  // a genuine pose beyond the 99.9 % gate is possible
  EXPECT_EQ(e.summary().reinitialisations, 0);
}

// An over-confident wrong start (P = 1e-4): every pose is gated until reinit_after_rejections in
// a row, then the filter starts again from the pose: converged after K pose periods (1 s at
// 10 Hz with K = 10), and it held its ground before.
TEST(Se2Estimator, ConvergesFromAWrongInitialPoseByReinitialisation) {
  const Drive d = test::SimulateDrive(NoisyPoses(), Eigen::Vector3d(0.0, 0.0, 0.0));
  const EstimatorOptions options;
  Se2Estimator e{options};
  e.Reset(kT0Us - 1000, Eigen::Vector3d(1.0, 0.0, 0.5), Eigen::Matrix3d::Identity() * 1e-4);
  int poses = 0, reinit_at = -1;
  double worst_after = 0.0, best_before = 1e9;
  Feed(d, 0, &e, [&](const test::PoseSample& p) {
    ++poses;
    if (e.last_pose_outcome() == PoseOutcome::kReinitialised && reinit_at < 0) reinit_at = poses;
    const double error = PositionError(e.Newest().X_WB, p.truth_WB);
    if (reinit_at < 0) best_before = std::min(best_before, error);
    if (reinit_at > 0) worst_after = std::max(worst_after, error);
  });
  EXPECT_EQ(reinit_at, options.reinit_after_rejections);
  EXPECT_EQ(e.summary().reinitialisations, 1);
  EXPECT_GE(e.summary().poses_gated, options.reinit_after_rejections - 1);
  EXPECT_GT(best_before, 0.8);  // the gate held until then
  EXPECT_LT(worst_after, 0.1);
  EXPECT_LT(PositionError(e.Newest().X_WB, d.poses.back().truth_WB), 0.05);
}

// Poses arriving 150 ms late (and odometry in between) give exactly the in-order estimate.
TEST(Se2Estimator, DelayedPosesGiveTheInOrderResult) {
  const Drive d = test::SimulateDrive(NoisyPoses(), Eigen::Vector3d(0.5, -1.0, 2.0));
  Se2Estimator in_order{EstimatorOptions{}}, delayed{EstimatorOptions{}};
  Feed(d, 0, &in_order);
  Feed(d, 150'000, &delayed);
  EXPECT_EQ(in_order.summary().delayed_inputs, 0);
  EXPECT_EQ(delayed.summary().delayed_inputs, static_cast<std::int64_t>(d.poses.size()) - 1);  // not the first
  EXPECT_GT(delayed.summary().replayed_events, 20 * static_cast<std::int64_t>(d.poses.size()) / 2);
  EXPECT_EQ(delayed.summary().poses_accepted, in_order.summary().poses_accepted);
  EXPECT_EQ(delayed.summary().poses_gated, in_order.summary().poses_gated);
  EXPECT_EQ(delayed.Newest().t_us, in_order.Newest().t_us);
  EXPECT_LT((delayed.Newest().X_WB - in_order.Newest().X_WB).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((delayed.Newest().P_WB - in_order.Newest().P_WB).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT(PositionError(delayed.Newest().X_WB, d.final_truth_WB), 0.05);
}

// Poses arriving 20 ms before the odometry up to their stamp (the odometry is the late
// stream): the odometry is inserted before them and the result is again the in-order one.
TEST(Se2Estimator, LateOdometryGivesTheInOrderResult) {
  const Drive d = test::SimulateDrive(NoisyPoses(), Eigen::Vector3d(-1.0, 0.5, -2.5));
  Se2Estimator in_order{EstimatorOptions{}}, early_poses{EstimatorOptions{}};
  Feed(d, 0, &in_order);
  Feed(d, -20'000, &early_poses);
  EXPECT_GT(early_poses.summary().delayed_inputs, 2 * static_cast<std::int64_t>(d.poses.size()));  // 3 per pose
  EXPECT_EQ(early_poses.summary().odometry_applied, in_order.summary().odometry_applied);
  EXPECT_EQ(early_poses.summary().poses_accepted, in_order.summary().poses_accepted);
  EXPECT_LT((early_poses.Newest().X_WB - in_order.Newest().X_WB).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((early_poses.Newest().P_WB - in_order.Newest().P_WB).cwiseAbs().maxCoeff(), 1e-15);
}

// A pose 2 m off after convergence is gated (the estimate does not move), the next good ones
// are accepted, and no re-initialisation happens: against the same drive without it, exactly
// one more pose is gated and the final estimate is the same.
TEST(Se2Estimator, GatingRejectsAnOutlierJump) {
  const Drive d = test::SimulateDrive(NoisyPoses(), Eigen::Vector3d(0.0, 0.0, 0.0));
  Se2Estimator clean{EstimatorOptions{}};
  Feed(d, 0, &clean);
  Se2Estimator e{EstimatorOptions{}};
  const std::size_t outlier = d.poses.size() / 2;
  std::size_t seen = 0;
  Eigen::Vector3d before_outlier, after_outlier;
  Feed(d, 0, &e, [&](const test::PoseSample&) {
    if (++seen != outlier) return;
    before_outlier = e.Newest().X_WB;
    const std::int64_t t_us = e.Newest().t_us + 1000;  // between two poses
    EXPECT_EQ(e.AddPose(t_us, before_outlier + Eigen::Vector3d(2.0, 0.0, 0.0)), EstimatorInput::kApplied);
    EXPECT_EQ(e.last_pose_outcome(), PoseOutcome::kGated);
    EXPECT_GT(e.summary().last_mahalanobis2, e.options().gate_chi2);
    after_outlier = e.Newest().X_WB;
  });
  EXPECT_LT(PositionError(before_outlier, after_outlier), 0.01);  // 1 ms of prediction only
  EXPECT_EQ(e.summary().poses_gated, clean.summary().poses_gated + 1);
  EXPECT_EQ(e.summary().poses_accepted, clean.summary().poses_accepted);
  EXPECT_EQ(e.summary().reinitialisations, 0);
  EXPECT_LT(PositionError(e.Newest().X_WB, clean.Newest().X_WB), 1e-3);
  EXPECT_LT(PositionError(e.Newest().X_WB, d.final_truth_WB), 0.05);
}

TEST(Se2Estimator, BadInputIsCountedAndChangesNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EstimatorOptions options;
  Se2Estimator e{options};
  e.AddPose(kT0Us, Eigen::Vector3d(1.0, 1.0, 0.0));
  e.AddOdometry(kT0Us + 10'000, 0.5, 0.1);
  e.AddPose(kT0Us + 20'000, Eigen::Vector3d(1.0, 1.0, 0.0));
  const EstimatorBelief before = e.Newest();
  EXPECT_EQ(e.AddOdometry(kT0Us + 30'000, nan, 0.0), EstimatorInput::kRejectedNotFinite);
  EXPECT_EQ(e.AddOdometry(kT0Us + 30'000, 0.0, inf), EstimatorInput::kRejectedNotFinite);
  EXPECT_EQ(e.AddOdometry(kT0Us + 10'000, 0.5, 0.1), EstimatorInput::kRejectedOutOfOrder);  // dt = 0
  EXPECT_EQ(e.AddOdometry(kT0Us + 5'000, 0.5, 0.1), EstimatorInput::kRejectedOutOfOrder);   // dt < 0
  EXPECT_EQ(e.AddPose(kT0Us + 30'000, Eigen::Vector3d(nan, 1.0, 0.0)), EstimatorInput::kRejectedNotFinite);
  EXPECT_EQ(e.AddPose(kT0Us + 30'000, Eigen::Vector3d(1.0, 1.0, -inf)), EstimatorInput::kRejectedNotFinite);
  EXPECT_EQ(e.AddPose(kT0Us + 20'000, Eigen::Vector3d(1.0, 1.0, 0.0)), EstimatorInput::kRejectedOutOfOrder);
  EXPECT_EQ(e.AddPose(kT0Us + 15'000, Eigen::Vector3d(1.0, 1.0, 0.0)), EstimatorInput::kRejectedOutOfOrder);
  EXPECT_EQ(e.last_pose_outcome(), PoseOutcome::kNone);
  EXPECT_EQ(e.Newest().t_us, before.t_us);
  EXPECT_EQ(e.Newest().X_WB, before.X_WB);
  EXPECT_EQ(e.Newest().P_WB, before.P_WB);
  // Too old: a pose more than max_delay_s behind the newest event.
  const std::int64_t late = kT0Us + 20'000 + static_cast<std::int64_t>(options.max_delay_s * 1e6) + 50'000;
  e.AddOdometry(late, 0.5, 0.1);
  EXPECT_EQ(e.AddPose(kT0Us + 30'000, Eigen::Vector3d(1.0, 1.0, 0.0)), EstimatorInput::kRejectedTooOld);
  const EstimatorSummary& s = e.summary();
  EXPECT_EQ(s.odometry_not_finite, 2);
  EXPECT_EQ(s.odometry_out_of_order, 2);
  EXPECT_EQ(s.poses_not_finite, 2);
  EXPECT_EQ(s.poses_out_of_order, 2);
  EXPECT_EQ(s.poses_too_old, 1);
  EXPECT_EQ(s.odometry_applied, 2);
  EXPECT_EQ(s.poses_initialised + s.poses_accepted, 2);
  EXPECT_NE(FormatEstimatorSummary(s).find("2 out of order"), std::string::npos) << FormatEstimatorSummary(s);
}

// With a small history, a pose older than the oldest event kept is too old; newer ones still
// apply (the evicted events' state is the base of later replays).
TEST(Se2Estimator, HistoryEvictionKeepsWorking) {
  EstimatorOptions options;
  options.history_capacity = 8;
  Se2Estimator e{options};
  e.AddPose(kT0Us, Eigen::Vector3d::Zero());
  for (int k = 1; k <= 20; ++k) e.AddOdometry(kT0Us + k * 5'000, 1.0, 0.0);
  EXPECT_EQ(e.history_size(), 8);
  // x(t) = t - 5 ms at 1 m/s (the odometry starts at 5 ms).
  EXPECT_EQ(e.AddPose(kT0Us + 40'000, Eigen::Vector3d(0.035, 0.0, 0.0)), EstimatorInput::kRejectedTooOld);
  EXPECT_EQ(e.AddPose(kT0Us + 90'000, Eigen::Vector3d(0.085, 0.0, 0.0)), EstimatorInput::kAppliedDelayed);
  EXPECT_EQ(e.last_pose_outcome(), PoseOutcome::kAccepted);
  EXPECT_NEAR(e.Newest().X_WB.x(), 0.095, 1e-9);  // odometry and pose agree
  EXPECT_EQ(e.Newest().t_us, kT0Us + 100'000);
}

}  // namespace
}  // namespace topay
