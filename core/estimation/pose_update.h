#pragma once
// The EKF update with a measured base pose z = (x m, y m, yaw rad) of the localisation.
//
// Measurement model h(X_WB) = X_WB, so H = I (3 x 3); R = diag(sxy^2, sxy^2, syaw^2).
//   innovation  nu = z - X_WB, yaw component wrapped to (-pi, pi]
//   S = H P H^T + R = P + R
//   squared Mahalanobis distance  m2 = nu^T S^-1 nu   (chi-square with 3 dof if consistent)
//   gain  K = P H^T S^-1 = P S^-1
//   X_WB <- X_WB + K nu (yaw wrapped)
//   P <- (I - K) P (I - K)^T + K R K^T   (Joseph form: symmetric, positive for any K)
// d X_WB+ / d X_WB = I - K and d X_WB+ / d z = K (tests check both by finite differences).

#include <Eigen/Core>

#include "core/estimation/estimator_options.h"

namespace topay {

/// R of EstimatorOptions: diag(pose_xy_stddev_m^2, pose_xy_stddev_m^2, pose_yaw_stddev_rad^2).
Eigen::Matrix3d PoseMeasurementNoise(const EstimatorOptions& options);

/// nu = z - X_WB with the yaw difference wrapped.
Eigen::Vector3d PoseInnovation(const Eigen::Vector3d& z_WB, const Eigen::Vector3d& X_WB);

/// m2 = nu^T (P + R)^-1 nu.
double PoseMahalanobis2(const Eigen::Vector3d& nu, const Eigen::Matrix3d& P_WB, const Eigen::Matrix3d& R);

/// Applies the update above to (*X_WB, *P_WB) (no gating here). Allocation-free.
void UpdatePose(const Eigen::Vector3d& z_WB, const Eigen::Matrix3d& R, Eigen::Vector3d* X_WB, Eigen::Matrix3d* P_WB);

}  // namespace topay
