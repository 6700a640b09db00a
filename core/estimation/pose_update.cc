#include "core/estimation/pose_update.h"

#include <Eigen/LU>

#include "core/common/angles.h"

namespace topay {

Eigen::Matrix3d PoseMeasurementNoise(const EstimatorOptions& o) {
  const double var_xy = o.pose_xy_stddev_m * o.pose_xy_stddev_m;
  return Eigen::Vector3d(var_xy, var_xy, o.pose_yaw_stddev_rad * o.pose_yaw_stddev_rad).asDiagonal();
}

Eigen::Vector3d PoseInnovation(const Eigen::Vector3d& z_WB, const Eigen::Vector3d& X_WB) {
  return {z_WB.x() - X_WB.x(), z_WB.y() - X_WB.y(), WrapAngle(z_WB.z() - X_WB.z())};
}

double PoseMahalanobis2(const Eigen::Vector3d& nu, const Eigen::Matrix3d& P_WB, const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d S = P_WB + R;  // H P H^T + R with H = I
  return nu.dot(S.inverse() * nu);
}

void UpdatePose(const Eigen::Vector3d& z_WB, const Eigen::Matrix3d& R, Eigen::Vector3d* X_WB, Eigen::Matrix3d* P_WB) {
  const Eigen::Vector3d nu = PoseInnovation(z_WB, *X_WB);
  const Eigen::Matrix3d S = *P_WB + R;
  const Eigen::Matrix3d K = *P_WB * S.inverse();  // K = P H^T S^-1
  *X_WB += K * nu;
  X_WB->z() = WrapAngle(X_WB->z());
  const Eigen::Matrix3d I_K = Eigen::Matrix3d::Identity() - K;
  *P_WB = I_K * *P_WB * I_K.transpose() + K * R * K.transpose();  // Joseph form
  *P_WB = 0.5 * (*P_WB + P_WB->transpose());
}

}  // namespace topay
