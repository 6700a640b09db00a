#pragma once

#include <Eigen/Core>

namespace topay {

/// One velocity command to the robot: base forward speed and yaw rate, joint velocities.
struct ControlCommand {
  double v_mps = 0.0;
  double omega_radps = 0.0;
  Eigen::VectorXd qd_radps;  ///< N joints.

  /// A zero command for num_joints joints (allocates once; reuse it).
  static ControlCommand Zero(int num_joints);
};

/// The inputs of a horizon of N steps: u_base column k = (v_k, omega_k) and qd_radps column
/// k = the joint velocities of step k, held over [t_k, t_k + step).
struct InputSequence {
  Eigen::Matrix2Xd u_base;     ///< 2 x N: row 0 v (m/s), row 1 omega (rad/s).
  Eigen::MatrixXd qd_radps;    ///< num_joints x N.

  /// Zero inputs for `steps` steps and num_joints joints.
  static InputSequence Zero(int steps, int num_joints);
  int steps() const { return static_cast<int>(u_base.cols()); }
  int num_joints() const { return static_cast<int>(qd_radps.rows()); }
  /// Column k as a command (allocation-free into a sized *command).
  void CommandAt(int k, ControlCommand* command) const;
  /// Every step set to `command` (a constant sequence).
  void Fill(const ControlCommand& command);
};

}  // namespace topay
