#pragma once

#include <Eigen/Core>

#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// The reference trajectory sampled at the horizon's times t_k = t0 + k step, k = 0..N:
/// poses and joints at every node, feed-forward inputs on every step (taken at its start).
struct ReferenceHorizon {
  Eigen::Matrix3Xd pose;      ///< 3 x (N + 1): x (m), y (m), yaw (rad) at t_k.
  Eigen::MatrixXd q_rad;      ///< num_joints x (N + 1).
  Eigen::Matrix2Xd u_base;    ///< 2 x N: v_ref (m/s), omega_ref (rad/s) at t_k.
  Eigen::MatrixXd qd_radps;   ///< num_joints x N: qd_ref at t_k.

  /// Sized for N steps and num_joints joints, every value zero.
  static ReferenceHorizon Zero(int steps, int num_joints);
  int steps() const { return static_cast<int>(u_base.cols()); }
  int num_joints() const { return static_cast<int>(q_rad.rows()); }
};

/// Samples `sampler` (a trajectory of duration_s) at t0_s + k step_s into *horizon (sized by
/// ReferenceHorizon::Zero). Times past the end take the end pose with zero feed-forward (the
/// robot holds the end); times before 0 take the start. *scratch is a sample sized for the
/// joints (MakeTrajectorySample). Allocation-free apart from what the sampler does.
void SampleReferenceHorizon(const TrajectorySampler& sampler, double duration_s, double t0_s,
                            double step_s, TrajectorySample* scratch, ReferenceHorizon* horizon);

/// Holds the joints of *horizon at the trajectory's joints at arm_t_s (clamped to [0,
/// duration]) on every node, with zero feed-forward: the arm waiting for a base that lags
/// (core/control/arm_pacing.h). The base's nodes are left as they are.
void HoldArmReference(const TrajectorySampler& sampler, double duration_s, double arm_t_s,
                      TrajectorySample* scratch, ReferenceHorizon* horizon);

}  // namespace topay
