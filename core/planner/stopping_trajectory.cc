#include "core/planner/stopping_trajectory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/validate/limit_ratios.h"

namespace topay {
namespace {

/// tau(t) of MakeStoppingTrajectory: t0 + t - T (u^3 - u^4 / 2), u = t / T (tau' = 1 - 3u^2 +
/// 2u^3); or, following the current trajectory to its end, min(t0 + t, end).
struct TimeScaling {
  double t0_s = 0.0;
  double duration_s = 1.0;  // T
  bool identity = false;
  double end_s = 0.0;       // the current trajectory's duration

  double Tau(double t_s) const {
    if (identity) return std::min(t0_s + t_s, end_s);
    const double u = std::clamp(t_s / duration_s, 0.0, 1.0);
    const double u3 = u * u * u;
    return t0_s + u * duration_s - duration_s * (u3 - 0.5 * u3 * u);
  }
};

/// [s - s0, yaw, q] of the current trajectory at time t_s, into `out` (D values).
void PathPoint(const ArcYawTrajectory& current, double t_s, double s0_m,
               TrajectorySample* sample, Eigen::Ref<Eigen::VectorXd> out) {
  current.Evaluate(t_s, sample);
  out(0) = sample->s_m - s0_m;
  out(1) = sample->state.yaw_rad;
  out.tail(current.num_joints()) = sample->state.q_rad;
}

/// The MINCO of the time-scaled path: head = the current trajectory's state and rates at t0
/// (tau'(0) = 1, tau''(0) = 0), waypoints r(tau) at the piece boundaries, tail at rest.
ArcYawTrajectory Build(const ArcYawTrajectory& current, const TimeScaling& scaling,
                       const StoppingTrajectoryOptions& options) {
  const int D = current.num_dims(), N = current.num_joints();
  const double T = scaling.duration_s;
  const int M = std::clamp(static_cast<int>(std::ceil(T / options.piece_duration_s - 1e-9)), 1,
                           options.max_pieces);
  TrajectorySample at = current.MakePoint();
  current.Evaluate(scaling.t0_s, &at);
  const double s0_m = at.s_m;
  Eigen::MatrixXd head(D, 3);
  head.col(0) << 0.0, at.state.yaw_rad, at.state.q_rad;
  head.col(1) << at.v_mps, at.omega_radps, at.qd_radps;
  head.col(2) << at.a_mps2, at.beta_radps2, at.qdd_radps2;
  const Eigen::Vector2d p0_W(at.state.x_m, at.state.y_m);
  Eigen::MatrixXd waypoints(D, M - 1);
  TrajectorySample sample = current.MakePoint();
  for (int i = 1; i < M; ++i) {
    PathPoint(current, scaling.Tau(T * i / M), s0_m, &sample, waypoints.col(i - 1));
  }
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(D, 3);  // at rest, eqs. (18)-(20)
  PathPoint(current, scaling.Tau(T), s0_m, &sample, tail.col(0));
  ArcYawTrajectory::Options trajectory_options;
  trajectory_options.integrator.panels_per_piece = options.panels_per_piece;
  ArcYawTrajectory stopping(N, M, trajectory_options);
  stopping.Update(p0_W, head, tail, waypoints, Eigen::VectorXd::Constant(M, T / M));
  return stopping;
}

/// Samples the stopping trajectory every check_period_s (and at its end): the worst limit
/// ratio, the joint position excess and the base's distance from the current path at tau(t).
/// True if within the limits.
bool Check(const ArcYawTrajectory& stopping, const ArcYawTrajectory& current,
           const TimeScaling& scaling, const BaseLimits& base, const JointLimits& joints,
           const StoppingTrajectoryOptions& options, StoppingTrajectory* result) {
  TrajectorySample sample = stopping.MakePoint(), on_path = current.MakePoint();
  const double T = stopping.duration_s();
  const int count = static_cast<int>(std::ceil(T / options.check_period_s));
  double worst = 0.0, excess = -1.0, deviation = 0.0;
  for (int k = 0; k <= count; ++k) {
    const double t = std::min(k * options.check_period_s, T);
    stopping.Evaluate(t, &sample);
    current.Evaluate(scaling.Tau(t), &on_path);
    worst = std::max(worst, WorstRateRatio(sample, base, joints).ratio);
    int joint = -1;
    excess = std::max(excess, MaxJointPositionExcess(sample.state.q_rad, joints, &joint));
    deviation = std::max(deviation, std::hypot(sample.state.x_m - on_path.state.x_m,
                                               sample.state.y_m - on_path.state.y_m));
  }
  result->worst_limit_ratio = worst;
  result->max_path_deviation_m = deviation;
  return worst <= 1.0 + options.limit_tolerance &&
         excess <= options.joint_position_tolerance_rad;
}

/// The first duration tried: duration_per_rate_ratio x the largest rate / acceleration limit
/// at t0, at least min_duration_s.
double InitialDuration(const TrajectorySample& at, const BaseLimits& base,
                       const JointLimits& joints, const StoppingTrajectoryOptions& options) {
  double ratio_s = std::max(std::abs(at.v_mps) / base.a_max_mps2,
                            std::abs(at.omega_radps) / base.beta_max_radps2);
  for (int j = 0; j < at.qd_radps.size(); ++j) {
    ratio_s = std::max(ratio_s, std::abs(at.qd_radps(j)) / joints.qdd_max_radps2(j));
  }
  return std::max(options.min_duration_s, options.duration_per_rate_ratio * ratio_s);
}

std::string CheckInputs(const ArcYawTrajectory& current, double t0_s, const BaseLimits& base,
                        const JointLimits& joints) {
  const int n = current.num_joints();
  if (!current.minco().solved()) return "the current trajectory has not been solved";
  if (!std::isfinite(t0_s)) return "t0 is not finite";
  if (joints.q_min_rad.size() != n || joints.q_max_rad.size() != n ||
      joints.qd_max_radps.size() != n || joints.qdd_max_radps2.size() != n) {
    return "joint limits are not sized for " + std::to_string(n) + " joints";
  }
  for (double limit : {base.v_max_mps, base.a_max_mps2, base.omega_max_radps,
                       base.beta_max_radps2}) {
    if (!(std::isfinite(limit) && limit > 0.0)) return "base limits must be finite and > 0";
  }
  if (!((joints.qdd_max_radps2.array() > 0.0).all() && (joints.qd_max_radps.array() > 0.0).all())) {
    return "joint rate limits must be > 0";
  }
  return "";
}

}  // namespace

void CheckStoppingTrajectoryOptions(const StoppingTrajectoryOptions& o) {
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("StoppingTrajectoryOptions: ") + what);
  };
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  require(positive(o.piece_duration_s), "piece_duration_s must be finite and > 0");
  require(o.max_pieces >= 1, "max_pieces must be >= 1");
  require(o.panels_per_piece >= 1, "panels_per_piece must be >= 1");
  require(positive(o.min_duration_s), "min_duration_s must be finite and > 0");
  require(std::isfinite(o.duration_per_rate_ratio) && o.duration_per_rate_ratio >= 0.0,
          "duration_per_rate_ratio must be finite and >= 0");
  require(std::isfinite(o.lengthen_factor) && o.lengthen_factor > 1.0,
          "lengthen_factor must be finite and > 1");
  require(o.max_attempts >= 1, "max_attempts must be >= 1");
  require(positive(o.check_period_s), "check_period_s must be finite and > 0");
  require(std::isfinite(o.limit_tolerance) && o.limit_tolerance >= 0.0,
          "limit_tolerance must be finite and >= 0");
  require(std::isfinite(o.joint_position_tolerance_rad) && o.joint_position_tolerance_rad >= 0.0,
          "joint_position_tolerance_rad must be finite and >= 0");
}

StoppingTrajectory MakeStoppingTrajectory(const ArcYawTrajectory& current, double t0_s,
                                          const BaseLimits& base_limits,
                                          const JointLimits& joint_limits,
                                          const StoppingTrajectoryOptions& options) {
  CheckStoppingTrajectoryOptions(options);
  StoppingTrajectory result;
  result.reason = CheckInputs(current, t0_s, base_limits, joint_limits);
  if (!result.reason.empty()) return result;
  TimeScaling scaling;
  scaling.end_s = current.duration_s();
  scaling.t0_s = std::clamp(t0_s, 0.0, scaling.end_s);
  const double remaining_s = scaling.end_s - scaling.t0_s;
  TrajectorySample at = current.MakePoint();
  current.Evaluate(scaling.t0_s, &at);
  double duration_s = InitialDuration(at, base_limits, joint_limits, options);
  for (int attempt = 0; attempt < options.max_attempts; ++attempt) {
    result.attempts = attempt + 1;
    // The robot stops at tau(T) = t0 + T / 2; beyond the end: follow the current trajectory
    // to its end (at rest there).
    scaling.identity = 0.5 * duration_s >= remaining_s;
    scaling.duration_s =
        scaling.identity ? std::max(remaining_s, options.min_duration_s) : duration_s;
    try {
      ArcYawTrajectory stopping = Build(current, scaling, options);
      const bool within = Check(stopping, current, scaling, base_limits, joint_limits, options,
                                &result);
      result.duration_s = stopping.duration_s();
      result.path_time_used_s = scaling.Tau(scaling.duration_s) - scaling.t0_s;
      result.follows_to_end = scaling.identity;
      if (within) {
        result.trajectory.emplace(std::move(stopping));
        result.reason.clear();
        return result;
      }
    } catch (const std::exception& e) {
      result.reason = std::string("could not build the stopping trajectory: ") + e.what();
      return result;
    }
    if (scaling.identity) break;  // the current trajectory's own remainder is beyond them
    duration_s *= options.lengthen_factor;
  }
  char text[200];
  std::snprintf(text, sizeof(text),
                "no stopping trajectory within the limits after %d attempts (last: %.3f s, worst "
                "limit ratio %.3f)",
                result.attempts, result.duration_s, result.worst_limit_ratio);
  result.reason = text;
  return result;
}

}  // namespace topay
