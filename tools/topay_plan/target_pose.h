#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace topay::plan {

/// End-effector target poses X_WE from command-line numbers.

/// From x, y, z (m) and roll, pitch, yaw (rad) about W's fixed axes, applied in that order
/// (the URDF convention, as the robot YAML's rpy): R_WE = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Isometry3d PoseFromXyzRpy(const Eigen::Vector3d& p_WE_m, double roll_rad, double pitch_rad,
                                 double yaw_rad);

/// From x, y, z (m) and a quaternion w, x, y, z whose norm is within 1e-3 of 1 (it is then
/// normalised, so numbers typed with 4 decimals are accepted). Throws std::invalid_argument
/// otherwise.
Eigen::Isometry3d PoseFromXyzQuaternion(const Eigen::Vector3d& p_WE_m,
                                        const Eigen::Vector4d& quaternion_wxyz);

/// Roll, pitch, yaw of R_WE as in PoseFromXyzRpy (pitch in [-pi/2, pi/2]), for reports.
Eigen::Vector3d RollPitchYaw(const Eigen::Matrix3d& R_WE);

}  // namespace topay::plan
