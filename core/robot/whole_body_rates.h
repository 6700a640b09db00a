#pragma once

#include <Eigen/Core>

namespace topay {

/// The first and second time derivatives of a whole-body motion in the arc length-yaw
/// variables of the paper (Sec. III-B: trajectory dims [s, yaw, q]): base forward speed
/// v = s', yaw rate omega = yaw', their derivatives a = s'', beta = yaw'', and the joint
/// velocities and accelerations. Together with a WholeBodyState (MovingState) it is the
/// head of a trajectory that must join a motion under way C2-continuously.
///
/// Empty joint vectors mean zero (so a default WholeBodyRates is "at rest" for any arm).
struct WholeBodyRates {
  double v_mps = 0.0;
  double omega_radps = 0.0;
  double a_mps2 = 0.0;
  double beta_radps2 = 0.0;
  Eigen::VectorXd qd_radps;    ///< N, or empty (zero).
  Eigen::VectorXd qdd_radps2;  ///< N, or empty (zero).

  /// Every rate zero, joint vectors sized for num_joints.
  static WholeBodyRates Zero(int num_joints);

  /// True if every entry is finite.
  bool IsFinite() const;
  /// True if every joint vector is empty or has num_joints entries.
  bool HasJointCount(int num_joints) const;
  /// True if every rate's magnitude is at most tolerance (default: exactly zero).
  bool IsAtRest(double tolerance = 0.0) const;

  /// qd (qdd) with num_joints entries: the stored vector, or zeros if it is empty.
  Eigen::VectorXd JointVelocities(int num_joints) const;
  Eigen::VectorXd JointAccelerations(int num_joints) const;
};

}  // namespace topay
