#include "core/optimization/piece_sampler.h"

#include "core/optimization/endpoint_relief.h"
#include "core/trajectory/quintic_basis.h"

namespace topay {
namespace {

constexpr int kBlock = kQuinticCoefficients;

}  // namespace

PieceSampler::PieceSampler(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                           const SignedDistanceField3& arm_field, const BaseLimits& base_limits,
                           const SamplePenaltyOptions& penalty_options,
                           const PathFitWeights& fit_weights, int num_pieces,
                           int panels_per_piece)
    : num_joints_(kinematics.num_joints()),
      num_pieces_(num_pieces),
      panels_per_piece_(panels_per_piece),
      fit_weights_(fit_weights),
      penalties_(kinematics, base_field, arm_field, base_limits, penalty_options) {
  const int D = num_joints_ + 2;
  dC_dp_.setZero(2, num_pieces * panels_per_piece + 1);
  sample_ = penalties_.MakeQuantities();
  sample_gradient_ = penalties_.MakeQuantities();
  values_.setZero(D, 4);
  weights_.setZero(D, 3);
}

bool PieceSampler::Run(const PieceSampleContext& context, int first, int end,
                       const std::stop_token& stop) {
  penalty_costs_.fill(0.0);
  path_fit_ = 0.0;
  if (context.with_gradient) dC_dp_.setZero();
  for (int piece = first; piece < end; ++piece) {
    if (stop.stop_requested()) return false;
    AddPiece(context, piece);
  }
  return true;
}

// Eq. (23) for piece j: sum_l w_l T_j / K P(t_l), t_l = l T_j / K, plus the path fit.
// With V the D x 4 values (position and derivatives 1-3 of every dimension) and G the D x 3
// weighted dCost/d(position, 1st, 2nd derivative) of the sample:
//   dCost/dc_j += [beta0 beta1 beta2] G^T,
//   dCost/dT_j += w_l / K P + (l / K) sum_d (G_d0 V_d1 + G_d1 V_d2 + G_d2 V_d3)   (t moves with T),
//   dCost/dp_g += the weighted dP/d(x, y) (the Simpson sample g = jK + l; its own dependence
//   on c and T is ArcYawTrajectory::PropagateGradient's).
void PieceSampler::AddPiece(const PieceSampleContext& context, int piece) {
  const int K = panels_per_piece_;
  const double T = (*context.durations_s)(piece);
  const auto c = context.trajectory->minco().coefficients().middleRows(kBlock * piece, kBlock);
  const Eigen::Matrix2Xd& positions = context.trajectory->positions().positions();
  const bool with_gradient = context.with_gradient;
  const bool fit = context.reference != nullptr;
  Eigen::Matrix<double, kBlock, 4> basis;
  for (int l = 0; l <= K; ++l) {
    const double t = T * l / K;
    for (int order = 0; order < 4; ++order) basis.col(order) = QuinticBasis(t, order);
    values_.noalias() = c.transpose() * basis;
    const int g = piece * K + l;
    SetSample(positions.col(g));
    const double trapezoid = (l == 0 || l == K) ? 0.5 : 1.0;
    const double w_time = trapezoid * T / K;  // eq. (23): T_j / K, trapezoid weights
    double penalty = 0.0;
    if (context.penalties_on) {
      PenaltyValues costs{};
      // The endpoint relief's ramp coordinate: the piece-index fraction, fixed per sample.
      const double u = PieceFraction(piece, static_cast<double>(l) / K, num_pieces_);
      penalty = penalties_.Evaluate(sample_, u, with_gradient ? &sample_gradient_ : nullptr,
                                    &costs);
      for (int term = 0; term < kNumPenaltyTerms; ++term) {
        penalty_costs_[term] += w_time * costs[term];
      }
    }
    if (!with_gradient && !fit) continue;
    if (with_gradient) {
      weights_.setZero();
      if (context.penalties_on) AddPenaltyWeights(w_time, g);
    }
    if (fit) {
      AddPathFit(*context.reference, piece * (K + 1) + l, trapezoid / K, positions.col(g), g,
                 with_gradient);
    }
    if (!with_gradient) continue;
    context.dC_dc->middleRows(kBlock * piece, kBlock).noalias() +=
        basis.leftCols<3>() * weights_.transpose();
    const double dcost_dt = (weights_.array() * values_.rightCols<3>().array()).sum();
    (*context.dC_dT)(piece) += trapezoid / K * penalty + static_cast<double>(l) / K * dcost_dt;
  }
}

void PieceSampler::SetSample(const Eigen::Ref<const Eigen::Vector2d>& p_W) {
  const int N = num_joints_;
  sample_.x_m = p_W(0);
  sample_.y_m = p_W(1);
  sample_.yaw_rad = values_(1, 0);
  sample_.v_mps = values_(0, 1);
  sample_.a_mps2 = values_(0, 2);
  sample_.omega_radps = values_(1, 1);
  sample_.beta_radps2 = values_(1, 2);
  sample_.q_rad = values_.col(0).tail(N);
  sample_.qd_radps = values_.col(1).tail(N);
  sample_.qdd_radps2 = values_.col(2).tail(N);
}

void PieceSampler::AddPenaltyWeights(double w_time, int g) {
  const int N = num_joints_;
  const SampleQuantities& d = sample_gradient_;
  weights_(0, 1) = w_time * d.v_mps;
  weights_(0, 2) = w_time * d.a_mps2;
  weights_(1, 0) = w_time * d.yaw_rad;
  weights_(1, 1) = w_time * d.omega_radps;
  weights_(1, 2) = w_time * d.beta_radps2;
  weights_.col(0).tail(N) = w_time * d.q_rad;
  weights_.col(1).tail(N) = w_time * d.qd_radps;
  weights_.col(2).tail(N) = w_time * d.qdd_radps2;
  dC_dp_(0, g) += w_time * d.x_m;
  dC_dp_(1, g) += w_time * d.y_m;
}

// Stage 1: w_fit (|p - p_ref|^2 + w_angle ((yaw - yaw_ref)^2 + |q - q_ref|^2)) with the
// trapezoid weight / K.
void PieceSampler::AddPathFit(const PathReference& reference, int r, double w_fit,
                              const Eigen::Ref<const Eigen::Vector2d>& p_W, int g,
                              bool with_gradient) {
  const int N = num_joints_;
  const Eigen::Vector2d dp = p_W - reference.p_W.col(r);
  const double dyaw = sample_.yaw_rad - reference.yaw_rad(r);
  const double a = fit_weights_.angle, b = fit_weights_.position;
  double dq_sq = 0.0;
  for (int k = 0; k < N; ++k) {
    const double e = sample_.q_rad(k) - reference.q_rad(k, r);
    dq_sq += e * e;
    if (with_gradient) weights_(2 + k, 0) += w_fit * 2.0 * a * e;
  }
  path_fit_ += w_fit * (b * dp.squaredNorm() + a * (dyaw * dyaw + dq_sq));
  if (with_gradient) {
    weights_(1, 0) += w_fit * 2.0 * a * dyaw;
    dC_dp_.col(g) += w_fit * 2.0 * b * dp;
  }
}

}  // namespace topay
