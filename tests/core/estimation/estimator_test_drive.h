#pragma once
// A simulated drive for the estimator's tests: the true base integrated at 1 kHz with wheel
// slip (a relative error of v and omega, first-order Gauss-Markov as in sim/plant), the wheel
// odometry (the commanded v, omega: what the wheels turn) at odometry_rate_hz, and the
// localisation (truth + white noise) at pose_rate_hz. Seeded: same seed, same drive.

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/common/random.h"
#include "core/estimation/se2_motion.h"

namespace topay::test {

inline constexpr std::int64_t kT0Us = 1'700'000'000'000'000;  // a wall-clock utime

struct DriveOptions {
  double v_mps = 0.5;                ///< forward speed
  double omega_radps = 0.2;          ///< yaw rate amplitude
  double omega_period_s = 0.0;       ///< > 0: omega = amplitude cos(2 pi t / period); 0: constant
  double duration_s = 20.0;
  double slip_stddev = 0.0;          ///< relative slip std dev (v and omega, independent)
  double slip_correlation_s = 0.5;
  double odometry_rate_hz = 200.0;
  double pose_rate_hz = 10.0;
  double pose_xy_stddev_m = 0.0;
  double pose_yaw_stddev_rad = 0.0;
  std::uint64_t seed = 1;
};

struct OdometrySample {
  std::int64_t t_us;
  double v_mps, omega_radps;
};
struct PoseSample {
  std::int64_t t_us;
  Eigen::Vector3d z_WB, truth_WB;
};
struct Drive {
  std::vector<OdometrySample> odometry;
  std::vector<PoseSample> poses;
  Eigen::Vector3d final_truth_WB;
  std::int64_t end_t_us;
};

inline Drive SimulateDrive(const DriveOptions& o, const Eigen::Vector3d& start_WB) {
  constexpr double kStepS = 1e-3;
  Rng rng(o.seed);
  const double decay = std::exp(-kStepS / o.slip_correlation_s);
  const double drive = o.slip_stddev * std::sqrt(1.0 - decay * decay);
  double slip_v = o.slip_stddev * rng.Normal(), slip_w = o.slip_stddev * rng.Normal();  // stationary start
  const auto omega_at = [&](double t) {
    return o.omega_period_s > 0 ? o.omega_radps * std::cos(2 * M_PI * t / o.omega_period_s) : o.omega_radps;
  };
  Drive d;
  Eigen::Vector3d X = start_WB;
  const int steps = static_cast<int>(std::lround(o.duration_s / kStepS));
  const int odometry_every = static_cast<int>(std::lround(1.0 / (o.odometry_rate_hz * kStepS)));
  const int pose_every = static_cast<int>(std::lround(1.0 / (o.pose_rate_hz * kStepS)));
  for (int k = 0; k <= steps; ++k) {
    const double t = k * kStepS;
    const std::int64_t t_us = kT0Us + static_cast<std::int64_t>(k) * 1000;
    if (k % odometry_every == 0) d.odometry.push_back({t_us, o.v_mps, omega_at(t)});
    if (k % pose_every == 0) {
      const Eigen::Vector3d noise(o.pose_xy_stddev_m * rng.Normal(), o.pose_xy_stddev_m * rng.Normal(),
                                  o.pose_yaw_stddev_rad * rng.Normal());
      Eigen::Vector3d z = X + noise;
      z.z() = std::remainder(z.z(), 2 * M_PI);
      d.poses.push_back({t_us, z, X});
    }
    if (k == steps) break;
    // The true motion over this millisecond: what the wheels drive times (1 + slip).
    slip_v = decay * slip_v + drive * rng.Normal();
    slip_w = decay * slip_w + drive * rng.Normal();
    X = MoveAlongArc(X, {o.v_mps * (1.0 + slip_v), omega_at(t) * (1.0 + slip_w), kStepS});
  }
  d.final_truth_WB = X;
  d.end_t_us = kT0Us + static_cast<std::int64_t>(steps) * 1000;
  return d;
}

}  // namespace topay::test
