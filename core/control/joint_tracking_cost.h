#pragma once

#include <Eigen/Core>
#include <ceres/cost_function.h>

#include "core/control/nmpc_options.h"
#include "core/control/reference_horizon.h"

namespace topay {

/// One joint's NMPC residuals over the horizon (the joints are integrators, linear and
/// independent of each other and of the base, so each is its own small problem), with an
/// analytic Jacobian: one parameter block qd = (qd_0 .. qd_N-1) (N), 3 N residuals:
///   [0, N)   position: sqrt(w_q f_k) (q_k+1 - q_ref,k+1), q_k+1 = q_0 + dt sum_{i <= k} qd_i
///   [N, 2N)  input:    sqrt(w_qd) (qd_k - qd_ref,k)
///   [2N, 3N) rate and rate limit, rate = (qd_k - qd_k-1) / dt_k:
///            sqrt(w_qdd) rate + sqrt(w_lim) sign(rate) max(0, |rate| - qdd_max)
/// with qd_-1 the last command, dt_0 = control_period_s, dt_k = step_s (k >= 1).
class JointTrackingCost final : public ceres::CostFunction {
 public:
  JointTrackingCost(const NmpcOptions& options, int joint, double qdd_max_radps2);

  /// The solve's data: the joint's (predicted) position, the reference (by pointer: it must
  /// outlive the solve) and the joint's last velocity command.
  void SetProblem(double q0_rad, const ReferenceHorizon* reference, double qd_last_radps);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  int steps_;
  int joint_;
  double qdd_max_radps2_;
  NmpcOptions options_;
  double q0_rad_ = 0.0;
  const ReferenceHorizon* reference_ = nullptr;
  double qd_last_radps_ = 0.0;
};

}  // namespace topay
