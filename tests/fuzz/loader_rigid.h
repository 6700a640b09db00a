#pragma once
// What the loader targets require of a pose a loader builds (a joint origin, an end-effector
// frame, a goal): a finite rigid transform.

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay::fuzz {

/// Finite, with an orthonormal rotation part of determinant +1 (to `tolerance`).
inline bool IsRigid(const Eigen::Isometry3d& X, double tolerance = 1e-9) {
  if (!X.matrix().allFinite()) return false;
  const Eigen::Matrix3d R = X.linear();
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= tolerance &&
         std::abs(R.determinant() - 1.0) <= tolerance;
}

}  // namespace topay::fuzz
