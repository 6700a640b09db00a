#include "core/optimization/flatness_objective.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>

#include "core/optimization/flat_yaw.h"
#include "core/optimization/joint_map.h"
#include "core/optimization/smooth_penalty.h"
#include "core/optimization/time_map.h"
#include "core/trajectory/quintic_basis.h"

namespace topay {
namespace {

constexpr int kBlock = kQuinticCoefficients;

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("FlatnessObjective: " + message);
}

// The options' own ranges (throws std::invalid_argument naming the field).
void CheckFlatnessObjectiveOptions(const FlatnessObjectiveOptions& options) {
  Require(options.panels_per_piece >= 1, "panels_per_piece must be >= 1");
  Require(options.stop_panel_factor >= 1, "stop_panel_factor must be >= 1");
  Require(std::isfinite(options.time_weight) && options.time_weight >= 0.0,
          "time_weight must be finite and >= 0");
  Require(std::isfinite(options.min_speed_mps) && options.min_speed_mps >= 0.0,
          "min_speed_mps must be finite and >= 0");
  Require(std::isfinite(options.min_speed_weight) && options.min_speed_weight >= 0.0,
          "min_speed_weight must be finite and >= 0");
  Require(std::isfinite(options.min_speed_smoothing_mu) && options.min_speed_smoothing_mu > 0.0,
          "min_speed_smoothing_mu must be finite and > 0");
  Require(options.stop_acceleration_fraction > 0.0 && options.stop_acceleration_fraction < 1.0,
          "stop_acceleration_fraction must be in (0, 1)");
}

}  // namespace

FlatnessObjective::FlatnessObjective(const Kinematics& kinematics,
                                     const SignedDistanceField2& base_field,
                                     const SignedDistanceField3& arm_field,
                                     const BaseLimits& base_limits, const WholeBodyState& start,
                                     const Eigen::Isometry3d& X_WE_goal, int num_pieces,
                                     const FlatnessObjectiveOptions& options)
    : kinematics_(kinematics),
      options_(options),
      num_pieces_(num_pieces),
      num_joints_(kinematics.num_joints()),
      penalties_(kinematics, base_field, arm_field, base_limits, options.penalties),
      end_effector_(kinematics, X_WE_goal),
      minco_(kinematics.num_joints() + 2, std::max(num_pieces, 1)) {
  Require(num_pieces >= 1, "num_pieces = " + std::to_string(num_pieces) + " must be >= 1");
  CheckFlatnessObjectiveOptions(options);
  Require(std::isfinite(base_limits.a_max_mps2) && base_limits.a_max_mps2 > 0.0,
          "base_limits.a_max_mps2 must be finite and > 0");
  Require(start.num_joints() == num_joints_,
          "start state has " + std::to_string(start.num_joints()) + " joints, the robot " +
              std::to_string(num_joints_));
  Require(start.IsFinite(), "start state is not finite");
  Require(X_WE_goal.matrix().allFinite(), "goal pose X_WE_goal is not finite");
  const int D = num_dims(), M = num_pieces_, N = num_joints_;
  const Eigen::VectorXd arc_weights = options.jerk_weights.Weights(N);  // (s, yaw, q)
  jerk_weights_.resize(D);
  jerk_weights_(0) = jerk_weights_(1) = arc_weights(0);
  jerk_weights_.tail(N) = arc_weights.tail(N);
  const double margin = options.penalties.joint_position_margin_rad;
  joint_min_rad_ = kinematics.model().joint_limits.q_min_rad.array() + margin;
  joint_max_rad_ = kinematics.model().joint_limits.q_max_rad.array() - margin;
  start_yaw_rad_ = start.yaw_rad;
  stop_acceleration_mps2_ = options.stop_acceleration_fraction * base_limits.a_max_mps2;
  // The start at rest, its acceleration along the start heading (the rest remedy).
  head_.setZero(D, 3);
  head_(0, 0) = start.x_m;
  head_(1, 0) = start.y_m;
  head_.col(0).tail(N) = start.q_rad;
  head_(0, 2) = stop_acceleration_mps2_ * std::cos(start.yaw_rad);
  head_(1, 2) = stop_acceleration_mps2_ * std::sin(start.yaw_rad);
  tail_.setZero(D, 3);
  waypoints_.setZero(D, M - 1);
  durations_s_.setOnes(M);
  dT_dtau_.setOnes(M);
  dq_dxi_.setOnes(N, M);
  dC_dc_.setZero(kBlock * M, D);
  dC_dT_.setZero(M);
  dC_dend_direct_.setZero(D + 1);
  minco_gradient_.Resize(D, M);
  sample_ = penalties_.MakeQuantities();
  sample_gradient_ = penalties_.MakeQuantities();
  values_.setZero(D, 5);
  weights_.setZero(D, 4);
  end_state_.q_rad.setZero(N);
}

int FlatnessObjective::panels(int piece) const {
  const bool stop_piece = piece == 0 || piece == num_pieces_ - 1;
  return options_.panels_per_piece * (stop_piece ? options_.stop_panel_factor : 1);
}

void FlatnessObjective::set_terms(const FlatnessTerms& terms) {
  terms_ = terms;
  penalties_.set_enabled(terms.penalties);
}

void FlatnessObjective::set_penalty_scales(const PenaltyValues& scales) {
  for (double scale : scales) {
    Require(std::isfinite(scale) && scale > 0.0, "penalty scales must be finite and > 0");
  }
  penalties_.set_weight_scales(scales);
}

void FlatnessObjective::set_multiplier(const Vector6d& lambda, double rho) {
  Require(lambda.allFinite(), "multiplier lambda is not finite");
  Require(std::isfinite(rho) && rho > 0.0, "rho = " + std::to_string(rho) + " must be > 0");
  lambda_ = lambda;
  rho_ = rho;
}

Eigen::VectorXd FlatnessObjective::Pack(const Eigen::VectorXd& durations_s,
                                        const Eigen::MatrixXd& waypoints,
                                        const Eigen::VectorXd& end) const {
  const int D = num_dims(), M = num_pieces_;
  Require(durations_s.size() == M && waypoints.rows() == D && waypoints.cols() == M - 1 &&
              end.size() == D + 1,
          "Pack: expected " + std::to_string(M) + " durations, " + std::to_string(D) + " x " +
              std::to_string(M - 1) + " waypoints and " + std::to_string(D + 1) +
              " end values (x_f, y_f, psi_f, q_f)");
  Require(waypoints.allFinite() && end.allFinite() && durations_s.allFinite(),
          "Pack: durations, waypoints or end not finite");
  Eigen::VectorXd x(num_parameters());
  for (int j = 0; j < M; ++j) x(j) = TauFromDuration(durations_s(j));  // throws if <= 0
  const auto pack_joints = [&](const auto& q, int offset) {
    for (int k = 0; k < num_joints_; ++k) {
      x(offset + k) = XiFromJoint(q(k), joint_min_rad_(k), joint_max_rad_(k));
    }
  };
  for (int i = 0; i + 1 < M; ++i) {
    x(M + i * D) = waypoints(0, i);
    x(M + i * D + 1) = waypoints(1, i);
    pack_joints(waypoints.col(i).tail(num_joints_), M + i * D + 2);
  }
  const int e = M + (M - 1) * D;
  x(e) = end(0);
  x(e + 1) = end(1);
  x(e + 2) = end(2);
  pack_joints(end.tail(num_joints_), e + 3);
  return x;
}

bool FlatnessObjective::Decode(const double* x) {
  const int D = num_dims(), M = num_pieces_, N = num_joints_;
  for (int p = 0; p < num_parameters(); ++p) {
    if (!std::isfinite(x[p])) return false;
  }
  for (int j = 0; j < M; ++j) durations_s_(j) = DurationFromTau(x[j], &dT_dtau_(j));
  const auto decode_joints = [&](int offset, int column, auto&& q) {
    for (int k = 0; k < N; ++k) {
      q(k) = JointFromXi(x[offset + k], joint_min_rad_(k), joint_max_rad_(k), &dq_dxi_(k, column));
    }
  };
  for (int i = 0; i + 1 < M; ++i) {
    waypoints_(0, i) = x[M + i * D];
    waypoints_(1, i) = x[M + i * D + 1];
    decode_joints(M + i * D + 2, i, waypoints_.col(i).tail(N));
  }
  const int e = M + (M - 1) * D;
  tail_(0, 0) = x[e];
  tail_(1, 0) = x[e + 1];
  end_yaw_rad_ = x[e + 2];
  decode_joints(e + 3, M - 1, tail_.col(0).tail(N));
  // The end at rest, decelerating along psi_f (the rest remedy).
  tail_(0, 2) = -stop_acceleration_mps2_ * std::cos(end_yaw_rad_);
  tail_(1, 2) = -stop_acceleration_mps2_ * std::sin(end_yaw_rad_);
  return true;
}

bool FlatnessObjective::Evaluate(const double* x, double* cost, double* gradient) {
  ++num_evaluations_;
  if (stop_.stop_requested()) {
    stopped_ = true;
    return false;
  }
  if (!Decode(x)) return false;
  const bool with_gradient = gradient != nullptr;
  try {
    minco_.Solve(head_, tail_, waypoints_, durations_s_);
    breakdown_ = FlatnessBreakdown();
    singular_ = false;
    if (with_gradient) {
      dC_dc_.setZero();
      dC_dT_.setZero();
      dC_dend_direct_.setZero();
    }
    if (terms_.jerk) {
      // Eq. (6), first term, on (x, y, q).
      breakdown_.jerk = JerkEnergy(minco_.coefficients(), durations_s_, jerk_weights_);
      if (with_gradient) {
        AddJerkEnergyGradient(minco_.coefficients(), durations_s_, jerk_weights_, dC_dc_,
                              dC_dT_);
      }
    }
    if (terms_.time) {
      breakdown_.time = options_.time_weight * durations_s_.sum();  // eq. (6), rho ||T||_1
      if (with_gradient) dC_dT_.array() += options_.time_weight;
    }
    for (int j = 0; j < num_pieces_; ++j) {
      if (stop_.stop_requested()) {
        stopped_ = true;
        return false;
      }
      AddPieceSamples(j, with_gradient);
      if (singular_) return false;
    }
    AddEndEffector(with_gradient);
    double total = breakdown_.jerk + breakdown_.time + breakdown_.end_effector +
                   breakdown_.min_speed;
    for (double term : breakdown_.penalties) total += term;
    breakdown_.total = total;
    if (!std::isfinite(total)) return false;
    *cost = total;
    if (with_gradient) {
      minco_.PropagateGradient(dC_dc_, dC_dT_, &minco_gradient_);
      WriteGradient(gradient);
      for (int p = 0; p < num_parameters(); ++p) {
        if (!std::isfinite(gradient[p])) return false;
      }
    }
    return true;
  } catch (const std::exception&) {
    return false;  // singular MINCO system or a failing kinematics update: back off
  }
}

// Eq. (23) with trapezoid weights on K_j panels, plus the minimum-speed term. G (D x 4) holds
// the weighted dCost/d(derivatives 0..3); dCost/dc_j += B G^T and
// dCost/dT_j += w_l / K_j P + (l / K_j) sum_d sum_k G_dk V_d,k+1 (t moves with T).
void FlatnessObjective::AddPieceSamples(int piece, bool with_gradient) {
  const int K = panels(piece);
  const int M = num_pieces_;
  const double T = durations_s_(piece);
  const auto c = minco_.coefficients().middleRows(kBlock * piece, kBlock);
  bool any_penalty = false;
  for (bool on : terms_.penalties) any_penalty = any_penalty || on;
  Eigen::Matrix<double, kBlock, 5> basis;
  for (int l = 0; l <= K; ++l) {
    const double t = T * l / K;
    for (int order = 0; order < 5; ++order) basis.col(order) = QuinticBasis(t, order);
    values_.noalias() = c.transpose() * basis;
    const Eigen::Vector2d u = values_.col(1).head<2>();
    const Eigen::Vector2d w = values_.col(2).head<2>();
    const Eigen::Vector2d z = values_.col(3).head<2>();
    const bool rest_start = piece == 0 && l == 0;
    const bool rest_end = piece == M - 1 && l == K;
    const bool rest = rest_start || rest_end;
    if (!rest && u.squaredNorm() < 1e-20) {
      singular_ = true;  // yaw undefined at an inner sample
      return;
    }
    SetSample(u, w, z, rest_start, rest_end);
    const double trapezoid = (l == 0 || l == K) ? 0.5 : 1.0;
    const double w_time = trapezoid * T / K;
    double penalty = 0.0;
    if (any_penalty) {
      PenaltyValues costs{};
      penalty = penalties_.Evaluate(sample_, with_gradient ? &sample_gradient_ : nullptr, &costs);
      for (int term = 0; term < kNumPenaltyTerms; ++term) {
        breakdown_.penalties[term] += w_time * costs[term];
      }
    }
    // Minimum speed: L(v_floor^2 - |u|^2), v_floor ramped to 0 towards a rest point.
    double floor_mps = options_.min_speed_mps;
    if (piece == 0) floor_mps *= static_cast<double>(l) / K;
    if (piece == M - 1) floor_mps *= static_cast<double>(K - l) / K;
    SmoothPenaltyValue speed;
    if (terms_.min_speed && !rest) {
      speed = SmoothPenalty(floor_mps * floor_mps - u.squaredNorm(),
                            options_.min_speed_smoothing_mu);
      const double value = options_.min_speed_weight * speed.value;
      penalty += value;
      breakdown_.min_speed += w_time * value;
    }
    if (!with_gradient) continue;
    weights_.setZero();
    Eigen::Vector2d dC_du = Eigen::Vector2d::Zero(), dC_dw = Eigen::Vector2d::Zero(),
                    dC_dz = Eigen::Vector2d::Zero();
    if (any_penalty) {
      AddPenaltyWeights(w_time, u, w, z, rest, rest_end, &dC_du, &dC_dw, &dC_dz);
    }
    if (terms_.min_speed && !rest) {
      dC_du += w_time * options_.min_speed_weight * speed.derivative * (-2.0) * u;
    }
    weights_.col(1).head<2>() += dC_du;
    weights_.col(2).head<2>() += dC_dw;
    weights_.col(3).head<2>() += dC_dz;
    dC_dc_.middleRows(kBlock * piece, kBlock).noalias() +=
        basis.leftCols<4>() * weights_.transpose();
    const double dcost_dt = (weights_.array() * values_.rightCols<4>().array()).sum();
    dC_dT_(piece) += trapezoid / K * penalty + static_cast<double>(l) / K * dcost_dt;
  }
}

void FlatnessObjective::SetSample(const Eigen::Vector2d& u, const Eigen::Vector2d& w,
                                  const Eigen::Vector2d& z, bool rest_start, bool rest_end) {
  const int N = num_joints_;
  sample_.x_m = values_(0, 0);
  sample_.y_m = values_(1, 0);
  if (rest_start || rest_end) {
    // Heading by continuity: the start yaw, or psi_f; no rates (FlatnessTrajectory).
    sample_.yaw_rad = rest_start ? start_yaw_rad_ : end_yaw_rad_;
    sample_.v_mps = 0.0;
    sample_.a_mps2 = stop_acceleration_mps2_ * (rest_start ? 1.0 : -1.0);
    sample_.omega_radps = 0.0;
    sample_.beta_radps2 = 0.0;
  } else {
    const FlatYaw flat = ComputeFlatYaw(u, w, z);
    sample_.yaw_rad = flat.yaw_rad;
    sample_.v_mps = flat.v_mps;
    sample_.a_mps2 = flat.a_mps2;
    sample_.omega_radps = flat.omega_radps;
    sample_.beta_radps2 = flat.beta_radps2;
  }
  sample_.q_rad = values_.col(0).tail(N);
  sample_.qd_radps = values_.col(1).tail(N);
  sample_.qdd_radps2 = values_.col(2).tail(N);
}

void FlatnessObjective::AddPenaltyWeights(double w_time, const Eigen::Vector2d& u,
                                          const Eigen::Vector2d& w, const Eigen::Vector2d& z,
                                          bool rest, bool rest_end, Eigen::Vector2d* dC_du,
                                          Eigen::Vector2d* dC_dw, Eigen::Vector2d* dC_dz) {
  const int N = num_joints_;
  const SampleQuantities& d = sample_gradient_;
  weights_(0, 0) = w_time * d.x_m;
  weights_(1, 0) = w_time * d.y_m;
  weights_.col(0).tail(N) = w_time * d.q_rad;
  weights_.col(1).tail(N) = w_time * d.qd_radps;
  weights_.col(2).tail(N) = w_time * d.qdd_radps2;
  if (rest_end) {
    dC_dend_direct_(2) += w_time * d.yaw_rad;
  } else if (!rest) {
    FlatYaw g;
    g.yaw_rad = w_time * d.yaw_rad;
    g.v_mps = w_time * d.v_mps;
    g.a_mps2 = w_time * d.a_mps2;
    g.omega_radps = w_time * d.omega_radps;
    g.beta_radps2 = w_time * d.beta_radps2;
    AddFlatYawGradient(u, w, z, g, dC_du, dC_dw, dC_dz);
  }
}

// PHR-ALM term of eq. (7) at z = (x_f, y_f, psi_f, q_f), all decision values themselves.
void FlatnessObjective::AddEndEffector(bool with_gradient) {
  end_state_.x_m = tail_(0, 0);
  end_state_.y_m = tail_(1, 0);
  end_state_.yaw_rad = end_yaw_rad_;
  end_state_.q_rad = tail_.col(0).tail(num_joints_);
  breakdown_.end_effector =
      end_effector_.Evaluate(end_state_, lambda_, rho_, terms_.end_effector, with_gradient);
  if (!terms_.end_effector || !with_gradient) return;
  const Eigen::VectorXd& dL_dz = end_effector_.dL_dz();
  dC_dend_direct_.head<3>() += dL_dz.head<3>();
  dC_dend_direct_.tail(num_joints_) += dL_dz.tail(num_joints_);
}

void FlatnessObjective::WriteGradient(double* gradient) const {
  const int D = num_dims(), M = num_pieces_, N = num_joints_;
  for (int j = 0; j < M; ++j) gradient[j] = minco_gradient_.durations(j) * dT_dtau_(j);  // (21)
  for (int i = 0; i + 1 < M; ++i) {
    const int offset = M + i * D;
    gradient[offset] = minco_gradient_.waypoints(0, i);
    gradient[offset + 1] = minco_gradient_.waypoints(1, i);
    for (int k = 0; k < N; ++k) {
      gradient[offset + 2 + k] = minco_gradient_.waypoints(2 + k, i) * dq_dxi_(k, i);  // (22)
    }
  }
  const int e = M + (M - 1) * D;
  const double a = stop_acceleration_mps2_;
  gradient[e] = minco_gradient_.tail(0, 0) + dC_dend_direct_(0);
  gradient[e + 1] = minco_gradient_.tail(1, 0) + dC_dend_direct_(1);
  // psi_f: directly, and through the tail acceleration -a (cos psi_f, sin psi_f).
  gradient[e + 2] = dC_dend_direct_(2) +
                    a * (minco_gradient_.tail(0, 2) * std::sin(end_yaw_rad_) -
                         minco_gradient_.tail(1, 2) * std::cos(end_yaw_rad_));
  for (int k = 0; k < N; ++k) {
    gradient[e + 3 + k] =
        (minco_gradient_.tail(2 + k, 0) + dC_dend_direct_(3 + k)) * dq_dxi_(k, M - 1);
  }
}

FlatnessTrajectoryData FlatnessObjective::TrajectoryData() const {
  FlatnessTrajectoryData data;
  data.head = head_;
  data.tail = tail_;
  data.waypoints = waypoints_;
  data.durations_s = durations_s_;
  data.start_yaw_rad = start_yaw_rad_;
  data.end_yaw_rad = end_yaw_rad_;
  return data;
}

}  // namespace topay
