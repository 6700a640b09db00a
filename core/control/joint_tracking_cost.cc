#include "core/control/joint_tracking_cost.h"

#include <cmath>

namespace topay {
namespace {

using RowMajorMap =
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

}  // namespace

JointTrackingCost::JointTrackingCost(const NmpcOptions& options, int joint, double qdd_max_radps2)
    : steps_(options.horizon_steps), joint_(joint), qdd_max_radps2_(qdd_max_radps2),
      options_(options) {
  set_num_residuals(3 * steps_);
  mutable_parameter_block_sizes()->push_back(steps_);
}

void JointTrackingCost::SetProblem(double q0_rad, const ReferenceHorizon* reference,
                                   double qd_last_radps) {
  q0_rad_ = q0_rad;
  reference_ = reference;
  qd_last_radps_ = qd_last_radps;
}

bool JointTrackingCost::Evaluate(double const* const* parameters, double* residuals,
                                 double** jacobians) const {
  const int N = steps_;
  const double dt = options_.step_s;
  const double* qd = parameters[0];
  Eigen::Map<Eigen::VectorXd> r(residuals, 3 * N);
  const bool with_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
  RowMajorMap J(with_jacobian ? jacobians[0] : nullptr, with_jacobian ? 3 * N : 0,
                with_jacobian ? N : 0);
  if (with_jacobian) J.setZero();

  const double sqrt_q = std::sqrt(options_.joint_weight);
  const double sqrt_qd = std::sqrt(options_.qd_weight);
  const double sqrt_qdd = std::sqrt(options_.qdd_weight);
  const double sqrt_limit = std::sqrt(options_.limit_weight);
  double q = q0_rad_;
  for (int k = 0; k < N; ++k) {
    q += dt * qd[k];  // q_k+1 = q_k + dt qd_k
    const double factor =
        k == N - 1 ? std::sqrt(options_.terminal_weight_factor) * sqrt_q : sqrt_q;
    // Position error: sqrt(w_q f_k) (q_k+1 - q_ref,k+1).
    r(k) = factor * (q - reference_->q_rad(joint_, k + 1));
    // Feed-forward deviation: sqrt(w_qd) (qd_k - qd_ref,k).
    r(N + k) = sqrt_qd * (qd[k] - reference_->qd_radps(joint_, k));
    // Rate (qd_k - qd_k-1) / dt_k, against the last command for k = 0.
    const double dt_k = k == 0 ? options_.control_period_s : dt;
    const double previous = k == 0 ? qd_last_radps_ : qd[k - 1];
    const double rate = (qd[k] - previous) / dt_k;
    // Rate and its limit in one residual:
    //   sqrt(w_qdd) rate + sqrt(w_lim) sign(rate) max(0, |rate| - qdd_max).
    const double excess = std::abs(rate) - qdd_max_radps2_;
    const bool beyond = excess > 0.0;
    const double sign = rate > 0.0 ? 1.0 : -1.0;
    r(2 * N + k) = sqrt_qdd * rate + (beyond ? sqrt_limit * sign * excess : 0.0);
    if (with_jacobian) {
      for (int i = 0; i <= k; ++i) J(k, i) = factor * dt;  // dq_k+1/dqd_i = dt (i <= k)
      J(N + k, k) = sqrt_qd;
      const double d_phi = (sqrt_qdd + (beyond ? sqrt_limit : 0.0)) / dt_k;
      J(2 * N + k, k) = d_phi;
      if (k > 0) J(2 * N + k, k - 1) = -d_phi;
    }
  }
  return true;
}

}  // namespace topay
