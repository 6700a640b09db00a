#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/optimization/pose_residual.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// The PHR augmented Lagrangian term of the end-effector constraint FK(end state) = X_WE_goal
/// (paper eq. (7)), shared by both parameterisations' objectives:
///   L = rho / 2 |r + lambda / rho|^2,  r = PoseResidual(X_WE(z), X_WE_goal) (6-D),
/// with its gradient dL/dz over the whole-body state z = (x, y, yaw, q). Allocation-free after
/// construction. The kinematics must outlive this object.
class EndEffectorAlmTerm {
 public:
  EndEffectorAlmTerm(const Kinematics& kinematics, const Eigen::Isometry3d& X_WE_goal);

  /// Updates the residual at `state` (always, so callers can report it). Returns L if
  /// `enabled` (0 otherwise), and fills dL_dz() when also `with_gradient`.
  double Evaluate(const WholeBodyState& state, const Vector6d& lambda, double rho, bool enabled,
                  bool with_gradient);

  const Vector6d& residual() const { return residual_; }
  /// dL/dz, z = (x, y, yaw, q1..qN), after an Evaluate with the gradient.
  const Eigen::VectorXd& dL_dz() const { return dL_dz_; }

 private:
  const Kinematics& kinematics_;
  Eigen::Isometry3d X_WE_goal_;
  KinematicsCache cache_;
  Eigen::MatrixXd J_WE_, dr_dz_;
  Eigen::VectorXd dL_dz_;
  Vector6d residual_ = Vector6d::Zero();
};

}  // namespace topay
