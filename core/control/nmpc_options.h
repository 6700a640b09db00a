#pragma once

#include "core/control/arm_pacing.h"

namespace topay {

/// Options of the NMPC tracker (core/control/nmpc_solver.h), Ceres style: every field has a
/// documented default; Check() throws std::invalid_argument naming the first bad field.
/// config/tracker/tracker.yaml lists the same defaults (loaded by the process, not by core/).
///
/// Costs (all squared, summed over the horizon's steps k = 0..N-1, states at k + 1):
///   position_weight (t . e_k+1)^2 + cross_track_weight (n . e_k+1)^2, e = p_WB - p_WB,ref
///     (t along the reference's heading, n across it; equal weights: |e|^2)
///   + yaw_weight wrap(yaw_k+1 - yaw_ref)^2
///   + joint_weight |q_k+1 - q_ref|^2           (x terminal_weight_factor at k + 1 = N)
///   + v_weight (v_k - v_ref)^2 + omega_weight (omega_k - omega_ref)^2
///   + qd_weight |qd_k - qd_ref|^2               (deviation from the feed-forward)
///   + (sqrt(a_weight) a_k + sqrt(limit_weight) sign(a_k) max(0, |a_k| - a_max))^2,
///     a_k = (v_k - v_k-1) / dt_k; likewise beta (beta_weight) and each joint (qdd_weight)
///     (input rates and their limits; k = 0 against the last command, dt_0 = control period)
///   + limit_weight max(0, |v_k| / v_max + |omega_k| / omega_max - 1)^2 (coupled, eq. (9)).
/// See core/control/base_tracking_cost.h and joint_tracking_cost.h.
struct NmpcOptions {
  // Horizon and timing.
  int horizon_steps = 25;          ///< N, steps of the horizon (25 x 40 ms = 1 s).
  double step_s = 0.04;            ///< Step of the horizon (s).
  double control_period_s = 0.02;  ///< Period between solves (50 Hz); the warm start shifts by it.
  double latency_s = 0.02;         ///< Known command latency: the state is predicted this far.
  double time_budget_s = 0.005;    ///< A solve over this falls back to the shifted previous solution.
  int max_iterations = 10;         ///< Levenberg-Marquardt iterations per solve (base and joints).

  // Cost weights (> 0 unless said otherwise).
  double position_weight = 100.0;       ///< Base position error along the reference's heading (1/m^2).
  double cross_track_weight = 1000.0;   ///< Base position error across the reference's heading (1/m^2):
                                        ///< heavier, so that a lag is closed along the path, not across a bend.
  double yaw_weight = 200.0;            ///< Base yaw error, wrapped (1/rad^2).
  double joint_weight = 100.0;          ///< Joint position errors (1/rad^2).
  double terminal_weight_factor = 5.0;  ///< Factor on the last step's pose and joint errors (>= 1).
  double v_weight = 1.0;                ///< v - v_ref (s^2/m^2).
  double omega_weight = 1.0;            ///< omega - omega_ref (s^2/rad^2).
  double qd_weight = 0.5;               ///< qd - qd_ref (s^2/rad^2).
  double a_weight = 0.05;               ///< Linear acceleration (s^4/m^2).
  double beta_weight = 0.05;            ///< Yaw acceleration (s^4/rad^2).
  double qdd_weight = 0.01;             ///< Joint accelerations (s^4/rad^2).
  double limit_weight = 10.0;           ///< Penalty on the squared excess over a penalised limit.

  // Safe behaviour (core/control/safe_stop.h).
  double stale_state_s = 0.1;  ///< A state older than this -> stop.
  double end_settle_s = 0.5;   ///< Keep tracking the end point this long after the end, then stop.

  /// The arm's reference waits for a base that lags (core/control/arm_pacing.h).
  ArmPacingOptions arm_pacing;

  /// Throws std::invalid_argument naming the first field out of range.
  void Check() const;
};

}  // namespace topay
