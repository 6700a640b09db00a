#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay {

/// Configuration of the mobile manipulator: base pose in the world W (the base frame B lies on
/// the ground, z = 0, at the midpoint of the wheel axle, x forward) and the arm's joint
/// positions q1..qN in the URDF's depth-first order.
///
/// The flat form used by Jacobians and optimizers is z = [x, y, yaw, q1, ..., qN].
struct WholeBodyState {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
  Eigen::VectorXd q_rad;

  int num_joints() const { return static_cast<int>(q_rad.size()); }

  /// The flat vector [x, y, yaw, q].
  Eigen::VectorXd ToVector() const;
  static WholeBodyState FromVector(const Eigen::VectorXd& z);

  /// X_WB: pose of the base frame in the world.
  Eigen::Isometry3d BasePose() const;

  /// True if every entry is finite.
  bool IsFinite() const;
};

}  // namespace topay
