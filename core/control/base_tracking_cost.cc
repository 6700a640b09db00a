#include "core/control/base_tracking_cost.h"

#include <cmath>

#include "core/common/angles.h"
#include "core/control/unicycle_rollout.h"

namespace topay {
namespace {

using RowMajorMap =
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

double Sign(double value) { return value > 0.0 ? 1.0 : (value < 0.0 ? -1.0 : 0.0); }

}  // namespace

BaseTrackingCost::BaseTrackingCost(const NmpcOptions& options, const TrackerLimits& limits)
    : steps_(options.horizon_steps), options_(options), limits_(limits) {
  set_num_residuals(8 * steps_);
  mutable_parameter_block_sizes()->push_back(2 * steps_);
  states_.setZero(3, steps_ + 1);
}

void BaseTrackingCost::SetProblem(const Eigen::Vector3d& x0, const ReferenceHorizon* reference,
                                  const Eigen::Vector2d& u_last) {
  x0_ = x0;
  reference_ = reference;
  u_last_ = u_last;
}

bool BaseTrackingCost::Evaluate(double const* const* parameters, double* residuals,
                                double** jacobians) const {
  const int N = steps_;
  const double dt = options_.step_s;
  const Eigen::Map<const Eigen::Matrix2Xd> u(parameters[0], 2, N);
  Eigen::Map<Eigen::VectorXd> r(residuals, 8 * N);
  RolloutUnicycle(x0_, u, dt, &states_);

  const bool with_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
  RowMajorMap J(with_jacobian ? jacobians[0] : nullptr, with_jacobian ? 8 * N : 0,
                with_jacobian ? 2 * N : 0);
  if (with_jacobian) {
    J.setZero();
    auto pose_rows = J.topRows(3 * N);
    RolloutJacobian(states_, u, dt, &pose_rows);
  }

  const double sqrt_along = std::sqrt(options_.position_weight);
  const double sqrt_cross = std::sqrt(options_.cross_track_weight);
  const double sqrt_yaw = std::sqrt(options_.yaw_weight);
  for (int j = 1; j <= N; ++j) {
    const double factor = j == N ? std::sqrt(options_.terminal_weight_factor) : 1.0;
    const int row = 3 * (j - 1);
    // Position error in the reference's frame (along its heading t and across it n):
    //   sqrt(w_p f_j) t . (p_WB,j - p_WB,ref,j),  sqrt(w_n f_j) n . (p_WB,j - p_WB,ref,j),
    // t = (cos yaw_ref, sin yaw_ref), n = (-sin yaw_ref, cos yaw_ref). Equal weights give the
    // world-frame |p - p_ref|^2; a heavier cross-track weight closes a lag along the path
    // instead of across a bend.
    const double c = std::cos(reference_->pose(2, j));
    const double s = std::sin(reference_->pose(2, j));
    const double dx = states_(0, j) - reference_->pose(0, j);
    const double dy = states_(1, j) - reference_->pose(1, j);
    r(row + 0) = factor * sqrt_along * (c * dx + s * dy);
    r(row + 1) = factor * sqrt_cross * (-s * dx + c * dy);
    // Yaw error wrapped to (-pi, pi] (d wrap / d yaw = 1 away from the cut).
    r(row + 2) = factor * sqrt_yaw * WrapAngle(states_(2, j) - reference_->pose(2, j));
    if (with_jacobian) {
      for (int col = 0; col < 2 * j; ++col) {  // state j depends on inputs 0..j-1 only
        const double d_x = J(row + 0, col), d_y = J(row + 1, col);
        J(row + 0, col) = factor * sqrt_along * (c * d_x + s * d_y);
        J(row + 1, col) = factor * sqrt_cross * (-s * d_x + c * d_y);
      }
      J.row(row + 2) *= factor * sqrt_yaw;
    }
  }

  const double sqrt_input[2] = {std::sqrt(options_.v_weight), std::sqrt(options_.omega_weight)};
  const double sqrt_rate[2] = {std::sqrt(options_.a_weight), std::sqrt(options_.beta_weight)};
  const double rate_max[2] = {limits_.base.a_max_mps2, limits_.base.beta_max_radps2};
  const double sqrt_limit = std::sqrt(options_.limit_weight);
  for (int k = 0; k < N; ++k) {
    const double dt_k = k == 0 ? options_.control_period_s : dt;
    for (int c = 0; c < 2; ++c) {
      const double previous = k == 0 ? u_last_(c) : u(c, k - 1);
      const double rate = (u(c, k) - previous) / dt_k;  // (u_k - u_k-1) / dt_k
      // Feed-forward deviation: sqrt(w) (u_k - u_ref,k).
      const int input_row = 3 * N + 2 * k + c;
      r(input_row) = sqrt_input[c] * (u(c, k) - reference_->u_base(c, k));
      // Input rate and its limit in one residual:
      //   phi(rate) = sqrt(w) rate + sqrt(w_lim) sign(rate) max(0, |rate| - rate_max),
      // the rate cost inside the limit, a slope steeper by sqrt(w_lim) beyond it.
      const int rate_row = 5 * N + 2 * k + c;
      const double excess = std::abs(rate) - rate_max[c];
      const bool beyond = excess > 0.0;
      r(rate_row) = sqrt_rate[c] * rate + (beyond ? sqrt_limit * Sign(rate) * excess : 0.0);
      if (with_jacobian) {
        J(input_row, 2 * k + c) = sqrt_input[c];
        const double d_phi = (sqrt_rate[c] + (beyond ? sqrt_limit : 0.0)) / dt_k;  // dphi/du_k
        J(rate_row, 2 * k + c) = d_phi;
        if (k > 0) J(rate_row, 2 * (k - 1) + c) = -d_phi;
      }
    }
    // Coupled v-omega hinge (eq. (9)): sqrt(w_lim) max(0, |v| / v_max + |omega| / omega_max - 1).
    const int coupled_row = 7 * N + k;
    const double ratio = std::abs(u(0, k)) / limits_.base.v_max_mps +
                         std::abs(u(1, k)) / limits_.base.omega_max_radps;
    const bool coupled_active = limits_.coupled_v_omega && ratio > 1.0;
    r(coupled_row) = coupled_active ? sqrt_limit * (ratio - 1.0) : 0.0;
    if (with_jacobian && coupled_active) {
      J(coupled_row, 2 * k) = sqrt_limit * Sign(u(0, k)) / limits_.base.v_max_mps;
      J(coupled_row, 2 * k + 1) = sqrt_limit * Sign(u(1, k)) / limits_.base.omega_max_radps;
    }
  }
  return true;
}

}  // namespace topay
