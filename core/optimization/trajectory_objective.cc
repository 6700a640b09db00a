#include "core/optimization/trajectory_objective.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/optimization/joint_map.h"
#include "core/optimization/time_map.h"
#include "core/trajectory/quintic_basis.h"

namespace topay {
namespace {

constexpr int kBlock = kQuinticCoefficients;

ArcYawTrajectory::Options TrajectoryOptions(int panels) {
  ArcYawTrajectory::Options options;
  options.integrator.panels_per_piece = panels;
  return options;
}

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("TrajectoryObjective: " + message);
}

}  // namespace

TrajectoryObjective::TrajectoryObjective(const Kinematics& kinematics,
                                         const SignedDistanceField2& base_field,
                                         const SignedDistanceField3& arm_field,
                                         const BaseLimits& base_limits,
                                         const WholeBodyState& start,
                                         const Eigen::Isometry3d& X_WE_goal, int num_pieces,
                                         const TrajectoryObjectiveOptions& options)
    : kinematics_(kinematics),
      options_(options),
      num_pieces_(num_pieces),
      num_joints_(kinematics.num_joints()),
      end_effector_(kinematics, X_WE_goal),
      trajectory_(kinematics.num_joints(), std::max(num_pieces, 1),
                  TrajectoryOptions(std::max(options.panels_per_piece, 1))) {
  Require(num_pieces >= 1, "num_pieces = " + std::to_string(num_pieces) + " must be >= 1");
  Require(options.panels_per_piece >= 1, "panels_per_piece must be >= 1");
  Require(options.sample_chunks >= 1, "sample_chunks must be >= 1");
  Require(std::isfinite(options.time_weight) && options.time_weight >= 0.0,
          "time_weight must be finite and >= 0");
  Require(options.path_fit_position_weight >= 0.0 && options.path_fit_angle_weight >= 0.0,
          "path fit weights must be >= 0");
  Require(start.num_joints() == num_joints_,
          "start state has " + std::to_string(start.num_joints()) + " joints, the robot " +
              std::to_string(num_joints_));
  Require(start.IsFinite(), "start state is not finite");
  Require(X_WE_goal.matrix().allFinite(), "goal pose X_WE_goal is not finite");
  const int D = num_dims(), M = num_pieces_, K = options.panels_per_piece;
  jerk_weights_ = options.jerk_weights.Weights(num_joints_);
  // The joint map's range: the limits less the penalty's joint margin, so waypoints and q_f
  // keep it (SamplePenalties checked that the margin leaves a range).
  const double margin = options.penalties.joint_position_margin_rad;
  joint_min_rad_ = kinematics.model().joint_limits.q_min_rad.array() + margin;
  joint_max_rad_ = kinematics.model().joint_limits.q_max_rad.array() - margin;
  p0_W_ = Eigen::Vector2d(start.x_m, start.y_m);
  // Conditions (15)-(17): the start at rest, s(0) = 0.
  head_.setZero(D, 3);
  head_(1, 0) = start.yaw_rad;
  head_.col(0).tail(num_joints_) = start.q_rad;
  tail_.setZero(D, 3);
  waypoints_.setZero(D, M - 1);
  durations_s_.setOnes(M);
  dT_dtau_.setOnes(M);
  dq_dxi_.setOnes(num_joints_, M);
  dC_dc_.setZero(kBlock * M, D);
  dC_dT_.setZero(M);
  dC_dp_.setZero(2, M * K + 1);
  dC_dend_direct_.setZero(D);
  minco_gradient_.Resize(D, M);
  const PathFitWeights fit{options.path_fit_position_weight, options.path_fit_angle_weight};
  const int chunks = std::min(options.sample_chunks, M);
  for (int c = 0; c < chunks; ++c) {
    samplers_.push_back(std::make_unique<PieceSampler>(
        kinematics, base_field, arm_field, base_limits, options.penalties, fit, M, K));
  }
  sampler_finished_.assign(chunks, 0);
  end_state_.q_rad.setZero(num_joints_);
}

void TrajectoryObjective::set_terms(const ObjectiveTerms& terms) {
  terms_ = terms;
  for (auto& sampler : samplers_) sampler->penalties().set_enabled(terms.penalties);
}

void TrajectoryObjective::set_start_rates(const WholeBodyRates& rates) {
  Require(rates.HasJointCount(num_joints_), "start rates must have 0 or " +
                                                std::to_string(num_joints_) + " joint entries");
  Require(rates.IsFinite(), "start rates are not finite");
  // Head velocity and acceleration (paper Sec. III-B: dims [s, yaw, q]; s' = v, yaw' = omega
  // and s'' = a, yaw'' = beta): the moving-start counterpart of conditions (15)-(17).
  head_(0, 1) = rates.v_mps;
  head_(1, 1) = rates.omega_radps;
  head_.col(1).tail(num_joints_) = rates.JointVelocities(num_joints_);
  head_(0, 2) = rates.a_mps2;
  head_(1, 2) = rates.beta_radps2;
  head_.col(2).tail(num_joints_) = rates.JointAccelerations(num_joints_);
}

void TrajectoryObjective::set_penalty_scales(const PenaltyValues& scales) {
  for (double scale : scales) {
    Require(std::isfinite(scale) && scale > 0.0, "penalty scales must be finite and > 0");
  }
  for (auto& sampler : samplers_) sampler->penalties().set_weight_scales(scales);
}

void TrajectoryObjective::set_tightening(const PenaltyTightening& t) {
  Require(std::isfinite(t.base_m) && t.base_m >= 0.0 && std::isfinite(t.arm_m) &&
              t.arm_m >= 0.0 && std::isfinite(t.joint_rad) && t.joint_rad >= 0.0,
          "tightening clearances and joint margin must be finite and >= 0");
  Require(t.rate_scale > 0.0 && t.rate_scale <= 1.0, "tightening rate_scale must be in (0, 1]");
  for (auto& sampler : samplers_) sampler->penalties().set_tightening(t);
}

void TrajectoryObjective::set_endpoint_relief(const EndpointRelief* relief) {
  for (auto& sampler : samplers_) sampler->penalties().set_endpoint_relief(relief);
}

void TrajectoryObjective::set_multiplier(const Vector6d& lambda, double rho) {
  Require(lambda.allFinite(), "multiplier lambda is not finite");
  Require(std::isfinite(rho) && rho > 0.0, "rho = " + std::to_string(rho) + " must be > 0");
  lambda_ = lambda;
  rho_ = rho;
}

void TrajectoryObjective::set_path_reference(const PathReference& reference) {
  const int samples = num_pieces_ * (panels_per_piece() + 1);
  Require(reference.p_W.cols() == samples && reference.yaw_rad.size() == samples &&
              reference.q_rad.rows() == num_joints_ && reference.q_rad.cols() == samples,
          "path reference must have " + std::to_string(samples) + " samples of " +
              std::to_string(num_joints_) + " joints");
  Require(reference.p_W.allFinite() && reference.yaw_rad.allFinite() &&
              reference.q_rad.allFinite(),
          "path reference is not finite");
  reference_ = reference;
  has_reference_ = true;
}

Eigen::VectorXd TrajectoryObjective::Pack(const Eigen::VectorXd& durations_s,
                                          const Eigen::MatrixXd& waypoints,
                                          const Eigen::VectorXd& end) const {
  const int D = num_dims(), M = num_pieces_;
  Require(durations_s.size() == M && waypoints.rows() == D && waypoints.cols() == M - 1 &&
              end.size() == D,
          "Pack: expected " + std::to_string(M) + " durations, " + std::to_string(D) + " x " +
              std::to_string(M - 1) + " waypoints and " + std::to_string(D) + " end values");
  Require(waypoints.allFinite() && end.allFinite(), "Pack: waypoints or end not finite");
  Eigen::VectorXd x(num_parameters());
  for (int j = 0; j < M; ++j) x(j) = TauFromDuration(durations_s(j));  // throws if <= 0
  const auto pack_state = [&](const Eigen::VectorXd& state, int offset) {
    x(offset) = state(0);
    x(offset + 1) = state(1);
    for (int k = 0; k < num_joints_; ++k) {
      x(offset + 2 + k) = XiFromJoint(state(2 + k), joint_min_rad_(k), joint_max_rad_(k));
    }
  };
  for (int i = 0; i + 1 < M; ++i) pack_state(waypoints.col(i), M + i * D);
  pack_state(end, M + (M - 1) * D);
  return x;
}

void TrajectoryObjective::Unpack(const double* x, Eigen::VectorXd* durations_s,
                                 Eigen::MatrixXd* waypoints, Eigen::VectorXd* end) const {
  const int D = num_dims(), M = num_pieces_;
  durations_s->resize(M);
  waypoints->resize(D, M - 1);
  end->resize(D);
  for (int j = 0; j < M; ++j) (*durations_s)(j) = DurationFromTau(x[j]);
  const auto unpack_state = [&](int offset, auto&& out) {
    out(0) = x[offset];
    out(1) = x[offset + 1];
    for (int k = 0; k < num_joints_; ++k) {
      out(2 + k) = JointFromXi(x[offset + 2 + k], joint_min_rad_(k), joint_max_rad_(k));
    }
  };
  for (int i = 0; i + 1 < M; ++i) unpack_state(M + i * D, waypoints->col(i));
  unpack_state(M + (M - 1) * D, *end);
}

bool TrajectoryObjective::Decode(const double* x) {
  const int D = num_dims(), M = num_pieces_;
  for (int p = 0; p < num_parameters(); ++p) {
    if (!std::isfinite(x[p])) return false;
  }
  for (int j = 0; j < M; ++j) durations_s_(j) = DurationFromTau(x[j], &dT_dtau_(j));
  // Eq. (22) inverted for every joint value; s and yaw as they are.
  const auto decode_state = [&](int offset, int column, auto&& out) {
    out(0) = x[offset];
    out(1) = x[offset + 1];
    for (int k = 0; k < num_joints_; ++k) {
      out(2 + k) = JointFromXi(x[offset + 2 + k], joint_min_rad_(k), joint_max_rad_(k),
                               &dq_dxi_(k, column));
    }
  };
  for (int i = 0; i + 1 < M; ++i) decode_state(M + i * D, i, waypoints_.col(i));
  decode_state(M + (M - 1) * D, M - 1, tail_.col(0));
  return true;
}

bool TrajectoryObjective::Evaluate(const double* x, double* cost, double* gradient) {
  ++num_evaluations_;
  if (stop_.stop_requested()) {
    stopped_ = true;
    return false;
  }
  if (!Decode(x)) return false;
  const bool with_gradient = gradient != nullptr;
  try {
    trajectory_.Update(p0_W_, head_, tail_, waypoints_, durations_s_);
    breakdown_ = ObjectiveBreakdown();
    if (with_gradient) {
      dC_dc_.setZero();
      dC_dT_.setZero();
      dC_dp_.setZero();
      dC_dend_direct_.setZero();
    }
    const MincoS3& minco = trajectory_.minco();
    if (terms_.jerk) {
      // Eq. (6), first term.
      breakdown_.jerk = JerkEnergy(minco.coefficients(), durations_s_, jerk_weights_);
      if (with_gradient) {
        AddJerkEnergyGradient(minco.coefficients(), durations_s_, jerk_weights_, dC_dc_, dC_dT_);
      }
    }
    if (terms_.time) {
      // Eq. (6), rho ||T||_1.
      breakdown_.time = options_.time_weight * durations_s_.sum();
      if (with_gradient) dC_dT_.array() += options_.time_weight;
    }
    AddSamples(with_gradient);
    if (stopped_) return false;
    AddEndEffector(with_gradient);
    double total = breakdown_.jerk + breakdown_.time + breakdown_.end_effector +
                   breakdown_.path_fit;
    for (double term : breakdown_.penalties) total += term;
    breakdown_.total = total;
    if (!std::isfinite(total)) return false;
    *cost = total;
    if (with_gradient) {
      trajectory_.PropagateGradient(dC_dp_, dC_dc_, dC_dT_, &minco_gradient_);
      WriteGradient(gradient);
      for (int p = 0; p < num_parameters(); ++p) {
        if (!std::isfinite(gradient[p])) return false;
      }
    }
    return true;
  } catch (const std::exception&) {
    // MINCO reports a numerically singular system for extreme durations; kinematics rejects
    // non-finite states. Either way this x is not usable: the line search backs off.
    return false;
  }
}

bool TrajectoryObjective::AnyPenalty() const {
  for (bool on : terms_.penalties) {
    if (on) return true;
  }
  return false;
}

bool TrajectoryObjective::NeedsGeometry() const {
  using T = PenaltyTerm;
  for (const T term : {T::kArmObstacle, T::kSelfCollision, T::kChassis}) {
    if (terms_.penalties[static_cast<int>(term)]) return true;
  }
  return false;
}

// Eq. (23) over all pieces, chunk by chunk (PieceSampler), then the chunks' sums in order.
void TrajectoryObjective::AddSamples(bool with_gradient) {
  const bool fit = terms_.path_fit && has_reference_;
  if (!AnyPenalty() && !fit) return;
  PieceSampleContext context;
  context.trajectory = &trajectory_;
  context.durations_s = &durations_s_;
  context.reference = fit ? &reference_ : nullptr;
  context.penalties_on = AnyPenalty();
  context.with_gradient = with_gradient;
  context.dC_dc = &dC_dc_;
  context.dC_dT = &dC_dT_;
  const int chunks = static_cast<int>(samplers_.size());
  const auto run_chunk = [&](int c) {
    sampler_finished_[c] = samplers_[c]->Run(context, c * num_pieces_ / chunks,
                                             (c + 1) * num_pieces_ / chunks, stop_);
  };
  if (chunks > 1 && NeedsGeometry()) {
    // Isolated: while this thread waits for the other chunks it takes no other work of the
    // arena (such as another candidate's whole optimization).
    tbb::this_task_arena::isolate([&] { tbb::parallel_for(0, chunks, run_chunk); });
  } else {
    for (int c = 0; c < chunks; ++c) run_chunk(c);
  }
  for (int c = 0; c < chunks; ++c) {
    const PieceSampler& sampler = *samplers_[c];
    if (!sampler_finished_[c]) stopped_ = true;
    for (int term = 0; term < kNumPenaltyTerms; ++term) {
      breakdown_.penalties[term] += sampler.penalty_costs()[term];
    }
    breakdown_.path_fit += sampler.path_fit();
    if (with_gradient) dC_dp_ += sampler.dC_dp();
  }
}

// PHR-ALM term of eq. (7): rho / 2 |r + lambda / rho|^2, r = PoseResidual(FK(end state)).
// d/dz = dr/dz^T (lambda + rho r), z = (x_f, y_f, yaw_f, q_f): x_f, y_f are the last Simpson
// sample, yaw_f and q_f the free end values themselves.
void TrajectoryObjective::AddEndEffector(bool with_gradient) {
  const int last = num_pieces_ * panels_per_piece();
  const Eigen::Matrix2Xd& positions = trajectory_.positions().positions();
  end_state_.x_m = positions(0, last);
  end_state_.y_m = positions(1, last);
  end_state_.yaw_rad = tail_(1, 0);
  end_state_.q_rad = tail_.col(0).tail(num_joints_);
  breakdown_.end_effector =
      end_effector_.Evaluate(end_state_, lambda_, rho_, terms_.end_effector, with_gradient);
  if (!terms_.end_effector || !with_gradient) return;
  const Eigen::VectorXd& dL_dz = end_effector_.dL_dz();
  dC_dp_(0, last) += dL_dz(0);
  dC_dp_(1, last) += dL_dz(1);
  dC_dend_direct_(1) += dL_dz(2);
  dC_dend_direct_.tail(num_joints_) += dL_dz.tail(num_joints_);
}

void TrajectoryObjective::WriteGradient(double* gradient) const {
  const int D = num_dims(), M = num_pieces_;
  // Time map, eq. (21): dC/dtau = dC/dT dT/dtau.
  for (int j = 0; j < M; ++j) gradient[j] = minco_gradient_.durations(j) * dT_dtau_(j);
  // Joint map, eq. (22): dC/dxi = dC/dq dq/dxi.
  const auto write_state = [&](int offset, int column, const auto& dC_dstate) {
    gradient[offset] = dC_dstate(0);
    gradient[offset + 1] = dC_dstate(1);
    for (int k = 0; k < num_joints_; ++k) {
      gradient[offset + 2 + k] = dC_dstate(2 + k) * dq_dxi_(k, column);
    }
  };
  for (int i = 0; i + 1 < M; ++i) write_state(M + i * D, i, minco_gradient_.waypoints.col(i));
  // The free end: through MINCO's tail and the end-effector term's direct dependence.
  const int end = M + (M - 1) * D;
  gradient[end] = minco_gradient_.tail(0, 0) + dC_dend_direct_(0);
  gradient[end + 1] = minco_gradient_.tail(1, 0) + dC_dend_direct_(1);
  for (int k = 0; k < num_joints_; ++k) {
    gradient[end + 2 + k] =
        (minco_gradient_.tail(2 + k, 0) + dC_dend_direct_(2 + k)) * dq_dxi_(k, M - 1);
  }
}

}  // namespace topay
