#pragma once

#include <Eigen/Core>
#include <ceres/cost_function.h>

#include "core/control/nmpc_options.h"
#include "core/control/reference_horizon.h"
#include "core/control/tracker_limits.h"

namespace topay {

/// The base's NMPC residuals over the whole horizon as one Ceres cost function with an
/// analytic Jacobian: one parameter block u = (v_0, omega_0, ..., v_N-1, omega_N-1) (2N),
/// 8 N residuals, in row blocks:
///   [0, 3N)   pose:   sqrt(w_p f_j) t_j . (p_j - p_ref,j) (along the reference's heading),
///                     sqrt(w_n f_j) n_j . (p_j - p_ref,j) (across it), sqrt(w_yaw f_j) wrap(yaw_j - yaw_ref,j)
///                     (t_j = (cos, sin) yaw_ref,j, n_j = (-sin, cos) yaw_ref,j; w_p = position_weight,
///                     w_n = cross_track_weight; j = 1..N, f_N = terminal_weight_factor, else 1;
///                     states by RolloutUnicycle)
///   [3N, 5N)  input:  sqrt(w_v) (v_k - v_ref,k), sqrt(w_omega) (omega_k - omega_ref,k)
///   [5N, 7N)  rate and rate limit, rate = (u_k - u_k-1) / dt_k, for v (w_a, a_max) and omega
///             (w_beta, beta_max):  sqrt(w) rate + sqrt(w_lim) sign(rate) max(0, |rate| - max)
///             (its square: the rate cost inside the limit; beyond it, the penalty
///             w_lim excess^2 plus a cross term 2 sqrt(w w_lim) |rate| excess, both >= 0)
///   [7N, 8N)  coupled hinge: sqrt(w_lim) max(0, |v_k| / v_max + |omega_k| / omega_max - 1)
///                     (zero rows when TrackerLimits::coupled_v_omega is off)
/// One residual per rate instead of a cost row and a hinge row: every row costs Ceres time
/// (the dense Jacobian is checked, copied and multiplied each iteration).
/// where u_-1 is the last command sent and dt_0 = control_period_s (the first input follows
/// the last command one control period later), dt_k = step_s for k >= 1.
///
/// Evaluate writes into member scratch buffers: one instance per (single-threaded) problem.
class BaseTrackingCost final : public ceres::CostFunction {
 public:
  BaseTrackingCost(const NmpcOptions& options, const TrackerLimits& limits);

  /// The solve's data: the (latency-predicted) base state x0 = (x, y, yaw), the reference
  /// (kept by pointer: it must outlive the solve) and the last command (v, omega).
  void SetProblem(const Eigen::Vector3d& x0, const ReferenceHorizon* reference,
                  const Eigen::Vector2d& u_last);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  int steps() const { return steps_; }

 private:
  int steps_;
  NmpcOptions options_;
  TrackerLimits limits_;
  Eigen::Vector3d x0_ = Eigen::Vector3d::Zero();
  const ReferenceHorizon* reference_ = nullptr;
  Eigen::Vector2d u_last_ = Eigen::Vector2d::Zero();
  mutable Eigen::Matrix3Xd states_;
};

}  // namespace topay
