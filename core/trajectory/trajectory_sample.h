#pragma once

#include <functional>

#include <Eigen/Core>

#include "core/robot/whole_body_state.h"

namespace topay {

/// A whole-body trajectory at one time: the pose and the rates the paper's dynamic limits
/// bound (eqs. (9)-(12)). The one sample type of the stack, whatever the parameterisation
/// (arc length-yaw: ArcYawTrajectory::Evaluate; the flatness baseline:
/// FlatnessTrajectory::Evaluate), used by the optimizer's checks, the validator and the
/// trajectory files.
struct TrajectorySample {
  double t_s = 0.0;
  WholeBodyState state;           ///< x_m, y_m, yaw_rad, q_rad (N).
  /// Arc length s(t) (m): the arc length-yaw trajectory's own dimension; other
  /// parameterisations leave it 0 unless their sampler integrates it.
  double s_m = 0.0;
  double v_mps = 0.0;             ///< Base forward speed (arc length-yaw: s').
  double omega_radps = 0.0;       ///< Yaw rate.
  double a_mps2 = 0.0;            ///< Base forward acceleration (dv/dt).
  double beta_radps2 = 0.0;       ///< Yaw acceleration.
  Eigen::VectorXd qd_radps;       ///< Joint velocities (N).
  Eigen::VectorXd qdd_radps2;     ///< Joint accelerations (N).
  /// Arc length-yaw only: [s''' (m/s^3), yaw''' (rad/s^3), q''' (rad/s^3)], D = 2 + N
  /// (sized by ArcYawTrajectory::MakePoint); empty elsewhere.
  Eigen::VectorXd jerk;
};

/// A sample sized for num_joints joints (jerk empty), every value zero (allocates once;
/// reuse it).
TrajectorySample MakeTrajectorySample(int num_joints);

/// Writes every field of *sample (sized by MakeTrajectorySample) for time t_s in
/// [0, duration]. May throw; the validator reports that as a failure at t_s.
using TrajectorySampler = std::function<void(double t_s, TrajectorySample* sample)>;

/// A trajectory as the validator sees it: a duration and a way to sample it.
///
/// make_sampler returns a sampler with its own buffers: each TrajectoryValidator::Validate
/// call makes one, so that concurrent validations of one SampledTrajectory share no mutable
/// state, and the sampler can keep scratch space to sample without allocating.
struct SampledTrajectory {
  double duration_s = 0.0;
  int num_joints = 0;
  std::function<TrajectorySampler()> make_sampler;
};

}  // namespace topay
