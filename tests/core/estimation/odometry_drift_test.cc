// Odometry-only drift (no pose after the start), docs/estimator.md "Drift bound":
// - noise-free odometry on a constant arc is exact (the estimate ends on the truth);
// - with wheel slip (relative error of v and omega, std dev s, first-order Gauss-Markov with
//   correlation time tau, as sim/plant) over T = 20 s at v = 0.5 m/s, omega = 0.2 rad/s, the
//   final position error of every one of 20 seeded drives stays below 4 sigma_bound with
//     sigma_bound^2 = 2 s^2 tau v^2 T  +  2 s^2 tau omega^2 v^2 T^3 / 3
//   (the distance error, plus the heading random walk's effect with every heading error
//   acting over the whole remaining path: an upper bound), their RMS below 1.5 sigma_bound, and
//   the filter's own covariance covers the errors (mean squared error / trace P_xy < 4).

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/estimation/se2_estimator.h"
#include "estimator_test_drive.h"

namespace topay {
namespace {

using test::kT0Us;

// Dead reckoning from the true start: one pose at the start, then odometry only.
Se2Estimator DeadReckon(const test::Drive& d) {
  Se2Estimator e{EstimatorOptions{}};
  e.AddPose(d.poses.front().t_us, d.poses.front().truth_WB);
  for (const test::OdometrySample& s : d.odometry) e.AddOdometry(s.t_us, s.v_mps, s.omega_radps);
  return e;
}

TEST(EstimatorDrift, NoiseFreeOdometryIsExact) {
  test::DriveOptions o;
  const test::Drive d = test::SimulateDrive(o, Eigen::Vector3d(1.0, 2.0, 0.3));
  const Se2Estimator e = DeadReckon(d);
  EXPECT_EQ(e.Newest().t_us, d.end_t_us);
  EXPECT_LT((e.Newest().X_WB.head<2>() - d.final_truth_WB.head<2>()).norm(), 1e-9);
  EXPECT_NEAR(std::remainder(e.Newest().X_WB.z() - d.final_truth_WB.z(), 2 * M_PI), 0.0, 1e-9);
}

TEST(EstimatorDrift, SlipDriftStaysWithinTheDerivedBound) {
  test::DriveOptions o;
  o.slip_stddev = 0.05;
  o.slip_correlation_s = 0.5;
  const double s2tau = 2 * o.slip_stddev * o.slip_stddev * o.slip_correlation_s;
  const double T = o.duration_s, v = o.v_mps, w = o.omega_radps;
  const double sigma_bound = std::sqrt(s2tau * v * v * T + s2tau * w * w * v * v * T * T * T / 3);
  constexpr int kSeeds = 20;
  double sum_squared = 0.0, worst = 0.0, sum_trace = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    o.seed = static_cast<std::uint64_t>(seed);
    const test::Drive d = test::SimulateDrive(o, Eigen::Vector3d(0.0, 0.0, 0.0));
    const Se2Estimator e = DeadReckon(d);
    const double error = (e.Newest().X_WB.head<2>() - d.final_truth_WB.head<2>()).norm();
    EXPECT_LT(error, 4 * sigma_bound) << "seed " << seed;
    worst = std::max(worst, error);
    sum_squared += error * error;
    sum_trace += e.Newest().P_WB(0, 0) + e.Newest().P_WB(1, 1);
  }
  const double rms = std::sqrt(sum_squared / kSeeds);
  const double filter_sigma = std::sqrt(sum_trace / kSeeds);
  std::printf("20 s odometry only, slip %.0f %%: sigma_bound %.3f m, RMS %.3f m, worst %.3f m, filter sqrt(tr P_xy) %.3f m\n",
              100 * o.slip_stddev, sigma_bound, rms, worst, filter_sigma);
  EXPECT_LT(rms, 1.5 * sigma_bound);
  EXPECT_LT(rms * rms / (filter_sigma * filter_sigma), 4.0);  // the covariance is not over-confident
  EXPECT_GT(rms, 0.0);
}

}  // namespace
}  // namespace topay
