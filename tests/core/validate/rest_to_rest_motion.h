#pragma once

// Shared by the core/validate tests: one-piece rest-to-rest arc length-yaw trajectories,
// whose every quantity has a closed form (the minimum-jerk ramp), so tests can compare the
// validator's figures with hand computations.

#include <cmath>

#include <Eigen/Core>

#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay::testing {

/// The quintic rest-to-rest ramp sigma(tau) = 10 tau^3 - 15 tau^4 + 6 tau^5 on [0, 1] (the
/// single MINCO s = 3 piece with zero velocity and acceleration at both ends) and its first
/// two derivatives with respect to tau. Peaks: sigma' = 15/8 at tau = 1/2, |sigma''| =
/// 10/sqrt(3) at tau = 1/2 -+ sqrt(3)/6.
inline double Ramp(double tau) { return tau * tau * tau * (10.0 - 15.0 * tau + 6.0 * tau * tau); }
inline double RampRate(double tau) { return 30.0 * tau * tau * (1.0 - tau) * (1.0 - tau); }
inline double RampAcceleration(double tau) {
  return 60.0 * tau - 180.0 * tau * tau + 120.0 * tau * tau * tau;
}

/// The smallest tau in [0, 1] with f(tau) >= level, for f increasing on [0, tau_peak]
/// (bisection to 1e-14).
template <typename F>
double FirstCrossing(F f, double level, double tau_peak = 1.0) {
  double low = 0.0, high = tau_peak;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (f(mid) >= level ? high : low) = mid;
  }
  return high;
}

/// A rest-to-rest motion: s from 0 to s_f, yaw from yaw0 to yaw_f, q from q0 to q_f, all
/// on the same ramp over duration_s, from base position p0_W. Optionally a non-zero end
/// speed (v at the end) to make a trajectory that does not end at rest.
struct RestToRest {
  Eigen::Vector2d p0_W = Eigen::Vector2d::Zero();
  double yaw0_rad = 0.0;
  double yaw_f_rad = 0.0;
  double s_f_m = 0.0;
  Eigen::VectorXd q0_rad;
  Eigen::VectorXd q_f_rad;
  double duration_s = 8.0;
  double v_end_mps = 0.0;
};

/// Updates a one-piece trajectory (ArcYawTrajectory(N, 1, ...)) to the motion.
inline void UpdateRestToRest(const RestToRest& motion, ArcYawTrajectory* trajectory) {
  const int dims = trajectory->num_dims();
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(dims, 3);
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(dims, 3);
  head(1, 0) = motion.yaw0_rad;
  head.col(0).tail(dims - 2) = motion.q0_rad;
  tail(0, 0) = motion.s_f_m;
  tail(1, 0) = motion.yaw_f_rad;
  tail(0, 1) = motion.v_end_mps;
  tail.col(0).tail(dims - 2) = motion.q_f_rad;
  trajectory->Update(motion.p0_W, head, tail, Eigen::MatrixXd::Zero(dims, 0),
                     Eigen::VectorXd::Constant(1, motion.duration_s));
}

}  // namespace topay::testing
