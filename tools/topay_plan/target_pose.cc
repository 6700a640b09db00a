#include "tools/topay_plan/target_pose.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace topay::plan {

Eigen::Isometry3d PoseFromXyzRpy(const Eigen::Vector3d& p_WE_m, double roll_rad, double pitch_rad,
                                 double yaw_rad) {
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  X_WE.linear() = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  X_WE.translation() = p_WE_m;
  return X_WE;
}

Eigen::Isometry3d PoseFromXyzQuaternion(const Eigen::Vector3d& p_WE_m,
                                        const Eigen::Vector4d& quaternion_wxyz) {
  const double norm = quaternion_wxyz.norm();
  if (!(std::abs(norm - 1.0) <= 1e-3)) {
    throw std::invalid_argument("quaternion (w, x, y, z) has norm " + std::to_string(norm) +
                                ", not 1 (within 1e-3)");
  }
  const Eigen::Vector4d q = quaternion_wxyz / norm;
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  X_WE.linear() = Eigen::Quaterniond(q(0), q(1), q(2), q(3)).toRotationMatrix();
  X_WE.translation() = p_WE_m;
  return X_WE;
}

Eigen::Vector3d RollPitchYaw(const Eigen::Matrix3d& R) {
  // R = Rz(yaw) Ry(pitch) Rx(roll): R(2,0) = -sin(pitch), R(2,1) = cos(pitch) sin(roll),
  // R(2,2) = cos(pitch) cos(roll), R(1,0) = sin(yaw) cos(pitch), R(0,0) = cos(yaw) cos(pitch).
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  if (std::abs(R(2, 0)) < 1.0 - 1e-12) {
    return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
  }
  // Gimbal lock: only yaw - roll (or yaw + roll) is defined; report roll = 0.
  return {0.0, pitch, std::atan2(-R(0, 1), R(1, 1))};
}

}  // namespace topay::plan
