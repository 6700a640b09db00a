#pragma once
// The odometry motion model of the differential-drive base on SE(2) and its Jacobians.
//
// State X_WB = (x, y, yaw): p_WB in m, the heading of B about W's z in rad. One odometry
// increment over dt at constant (v, omega) is an exact circular arc (the unicycle):
//   d = v dt (m), dpsi = omega dt (rad),
//   displacement in B:  p_B = d (s1(dpsi), c1(dpsi)),  s1(a) = sin(a) / a, c1(a) = (1 - cos a) / a
//   x' = x + cos(yaw) p_B.x - sin(yaw) p_B.y
//   y' = y + sin(yaw) p_B.x + cos(yaw) p_B.y
//   yaw' = wrap(yaw + dpsi)
// (s1 and c1 by their Taylor series for |a| < 1e-2, so a straight line is exact too.) Being
// exact, one step of 2 dt equals two steps of dt: where a pose measurement splits an odometry
// interval changes nothing in the mean.
// Jacobians: F = d(x', y', yaw') / d(x, y, yaw) = [1 0 -(y'-y); 0 1 (x'-x); 0 0 1] and
// G = d(x', y', yaw') / d(d, dpsi) = [R(yaw) (s1, c1), R(yaw) d (s1', c1'); 0 1].
// Process noise (EstimatorOptions): Q = G diag(var_d, var_dpsi) G^T + diag(qxy, qxy, qyaw) dt.

#include <Eigen/Core>

#include "core/estimation/estimator_options.h"

namespace topay {

/// One odometry increment: what the wheels report over dt.
struct OdometryIncrement {
  double v_mps = 0.0;        ///< forward speed along B's x, m/s
  double omega_radps = 0.0;  ///< yaw rate, rad/s
  double dt_s = 0.0;         ///< duration, s (>= 0)
};

/// The mean after the increment (yaw wrapped to (-pi, pi]). X_WB = (x m, y m, yaw rad).
Eigen::Vector3d MoveAlongArc(const Eigen::Vector3d& X_WB, const OdometryIncrement& u);

/// F = d MoveAlongArc / d X_WB at (X_WB, u).
Eigen::Matrix3d MotionJacobianState(const Eigen::Vector3d& X_WB, const OdometryIncrement& u);

/// G = d MoveAlongArc / d (d, dpsi) with d = v dt, dpsi = omega dt, at (X_WB, u).
Eigen::Matrix<double, 3, 2> MotionJacobianIncrement(const Eigen::Vector3d& X_WB, const OdometryIncrement& u);

/// Q of the increment (see the header comment), 3 x 3 in (x, y, yaw).
Eigen::Matrix3d MotionNoise(const Eigen::Vector3d& X_WB, const OdometryIncrement& u, const EstimatorOptions& options);

/// The EKF prediction: X_WB <- MoveAlongArc, P_WB <- F P F^T + Q. Allocation-free.
void PredictPose(const OdometryIncrement& u, const EstimatorOptions& options, Eigen::Vector3d* X_WB,
                 Eigen::Matrix3d* P_WB);

}  // namespace topay
