#include "core/optimization/warm_start.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/angles.h"
#include "core/planning/discrete_se2.h"

namespace topay {
namespace {

constexpr double kStillStep = 1e-9;  // steps shorter than this (m or rad) do not move

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("MakeWarmStart: " + message);
}

/// A run of consecutive same-kind steps (states first..last) and its trapezoid: the
/// quantity that takes longest (total travel, rate and acceleration limits) sets its time.
struct Run {
  int first = 0;
  int last = 0;
  double start_s = 0.0;
  double duration_s = 0.0;
  double total = 0.0;
  double rate = 1.0;
  double accel = 1.0;
  /// The quantity's rate at the run's first state (> 0 only for a first drive run from a
  /// moving start: the profile then begins at that speed, FromSpeedProfile).
  double initial_rate = 0.0;
};

/// A profile over `total` that begins at initial_rate r0 > 0 and ends at rest, within
/// rate_max and accel_max (issue 18, a moving start): accelerate from r0 to the peak, cruise,
/// brake; if braking at accel_max from r0 overshoots `total`, one constant deceleration of
/// r0^2 / (2 total) instead (the only one that stops there).
struct FromSpeedProfile {
  FromSpeedProfile(double total_in, double r0_in, double rate_max, double accel_max)
      : total(total_in), r0(std::min(r0_in, rate_max)), accel(accel_max) {
    if (total <= 0.5 * r0 * r0 / accel) {  // braking only: v(t) = r0 - d t
      braking_only = true;
      decel = 0.5 * r0 * r0 / std::max(total, kStillStep);
      duration = r0 / decel;
      return;
    }
    // Ramp r0 -> peak, cruise, peak -> 0: (peak^2 - r0^2) / 2a + peak^2 / 2a <= total.
    peak = std::min(rate_max, std::sqrt(accel * total + 0.5 * r0 * r0));
    ramp_up_time = (peak - r0) / accel;
    ramp_up_length = 0.5 * (peak * peak - r0 * r0) / accel;
    ramp_down_time = peak / accel;
    const double cruise_length = total - ramp_up_length - 0.5 * peak * peak / accel;
    duration = ramp_up_time + std::max(cruise_length, 0.0) / peak + ramp_down_time;
  }
  /// The time at which the travel reaches x in [0, total].
  double Time(double x) const {
    x = std::clamp(x, 0.0, total);
    if (braking_only) return (r0 - std::sqrt(std::max(r0 * r0 - 2.0 * decel * x, 0.0))) / decel;
    if (x <= ramp_up_length) return (std::sqrt(r0 * r0 + 2.0 * accel * x) - r0) / accel;
    const double braking_length = 0.5 * peak * peak / accel;
    if (x <= total - braking_length) return ramp_up_time + (x - ramp_up_length) / peak;
    return duration - std::sqrt(2.0 * (total - x) / accel);
  }
  /// The travel at time t (the inverse of Time).
  double Travel(double t) const {
    t = std::clamp(t, 0.0, duration);
    if (braking_only) return std::min(r0 * t - 0.5 * decel * t * t, total);
    if (t <= ramp_up_time) return r0 * t + 0.5 * accel * t * t;
    if (t <= duration - ramp_down_time) return ramp_up_length + peak * (t - ramp_up_time);
    const double left = duration - t;
    return total - 0.5 * accel * left * left;
  }

  double total, r0, accel;
  bool braking_only = false;
  double decel = 0.0, peak = 0.0, ramp_up_time = 0.0, ramp_up_length = 0.0;
  double ramp_down_time = 0.0, duration = 0.0;
};

/// The path as arrays: x, y, s, yaw (unwrapped), q per state; state 0 is the start. progress:
/// the travel of its run's trapezoid quantity from the run's first state to this one.
struct PathArrays {
  Eigen::VectorXd x, y, s, yaw;
  Eigen::MatrixXd q;  // N x states
  Eigen::VectorXd t;
  Eigen::VectorXd progress;
  std::vector<Run> runs;
  int size() const { return static_cast<int>(x.size()); }
};

/// Inverse of TrapezoidArrivalTime: the travel at time t of a rest-to-rest trapezoid.
double TrapezoidTravel(double t, double total, double rate_max, double accel_max) {
  const double peak = std::min(rate_max, std::sqrt(accel_max * total));
  const double ramp_time = peak / accel_max;
  const double ramp_length = 0.5 * peak * peak / accel_max;
  const double total_time = TrapezoidArrivalTime(total, total, rate_max, accel_max);
  if (t <= 0.0) return 0.0;
  if (t >= total_time) return total;
  if (t <= ramp_time) return 0.5 * accel_max * t * t;
  if (t <= total_time - ramp_time) return ramp_length + peak * (t - ramp_time);
  const double left = total_time - t;
  return total - 0.5 * accel_max * left * left;
}

PathArrays ToArrays(const WholeBodyPath& path, const WholeBodyState& start) {
  const int n = static_cast<int>(path.states.size());
  PathArrays a;
  a.x.resize(n);
  a.y.resize(n);
  a.s.resize(n);
  a.yaw.resize(n);
  a.q.resize(start.num_joints(), n);
  a.t.setZero(n);
  a.progress.setZero(n);
  for (int k = 0; k < n; ++k) {
    const WholeBodyState& state = k == 0 ? start : path.states[k];
    a.x(k) = state.x_m;
    a.y(k) = state.y_m;
    a.q.col(k) = state.q_rad;
    a.yaw(k) = k == 0 ? state.yaw_rad : a.yaw(k - 1) + WrapAngle(state.yaw_rad - a.yaw(k - 1));
    if (k == 0) {
      a.s(k) = 0.0;
      continue;
    }
    const Eigen::Vector2d step(a.x(k) - a.x(k - 1), a.y(k) - a.y(k - 1));
    // Signed arc length: backwards if the step points against the base's heading.
    const Eigen::Vector2d heading(std::cos(a.yaw(k - 1)) + std::cos(a.yaw(k)),
                                  std::sin(a.yaw(k - 1)) + std::sin(a.yaw(k)));
    a.s(k) = a.s(k - 1) + (step.dot(heading) >= 0.0 ? 1.0 : -1.0) * step.norm();
  }
  return a;
}

/// Rest-to-rest trapezoid over a run of length `total` at the given rate limits.
double RunTime(double total, double rate, double accel) {
  return total > 0.0 ? TrapezoidArrivalTime(total, total, rate, accel) : 0.0;
}

/// Times of every state: trapezoids over runs of same-kind steps (see MakeWarmStart).
/// start_speed_mps: the start's forward speed (0: at rest), used by the first run if it drives
/// in the speed's direction.
void TimeThePath(const BaseLimits& base, const JointLimits& joints, double fraction,
                 double start_speed_mps, PathArrays* a) {
  const int n = a->size(), num_joints = static_cast<int>(a->q.rows());
  // Per step: 0 = drive, 1 = turn in place / arm only.
  const auto kind = [&](int k) { return std::abs(a->s(k) - a->s(k - 1)) > kStillStep ? 0 : 1; };
  int first = 0;  // first state of the current run
  while (first < n - 1) {
    int last = first + 1;
    while (last < n - 1 && kind(last + 1) == kind(first + 1)) ++last;
    // Measures along the run: 0 distance, 1 yaw, 2.. joints; with their limits.
    const int num_measures = 2 + num_joints;
    std::vector<double> total(num_measures, 0.0), rate(num_measures), accel(num_measures);
    rate[0] = fraction * base.v_max_mps;
    accel[0] = fraction * base.a_max_mps2;
    rate[1] = fraction * base.omega_max_radps;
    accel[1] = fraction * base.beta_max_radps2;
    for (int j = 0; j < num_joints; ++j) {
      rate[2 + j] = fraction * joints.qd_max_radps(j);
      accel[2 + j] = fraction * joints.qdd_max_radps2(j);
    }
    const auto step_of = [&](int m, int k) {
      if (m == 0) return std::abs(a->s(k) - a->s(k - 1));
      if (m == 1) return std::abs(a->yaw(k) - a->yaw(k - 1));
      return std::abs(a->q(m - 2, k) - a->q(m - 2, k - 1));
    };
    for (int k = first + 1; k <= last; ++k) {
      for (int m = 0; m < num_measures; ++m) total[m] += step_of(m, k);
    }
    // A moving start: the first run, if it drives the way the base already moves, starts
    // its distance profile at that speed rather than at rest.
    // (Runs of no motion before it, e.g. a repeated start state, do not count: they take
    // under a microsecond.)
    const double drive_sign = a->s(first + 1) - a->s(first);
    const double initial_rate = a->t(first) < 1e-6 && kind(first + 1) == 0 &&
                                        start_speed_mps * drive_sign > 0.0
                                    ? std::abs(start_speed_mps)
                                    : 0.0;
    int dominant = 0;
    double run_time = 0.0;
    for (int m = 0; m < num_measures; ++m) {
      const double time =
          m == 0 && initial_rate > 0.0 && total[0] > 0.0
              ? FromSpeedProfile(total[0], initial_rate, rate[0], accel[0]).duration
              : RunTime(total[m], rate[m], accel[m]);
      if (time > run_time) {
        run_time = time;
        dominant = m;
      }
    }
    Run run{first, last, a->t(first), run_time, total[dominant], rate[dominant], accel[dominant],
            dominant == 0 ? initial_rate : 0.0};
    double progress = 0.0;
    for (int k = first + 1; k <= last; ++k) {
      progress += step_of(dominant, k);
      a->progress(k) = progress;
      a->t(k) = run.start_s + (run_time <= 0.0 ? 0.0
                               : run.initial_rate > 0.0
                                   ? FromSpeedProfile(run.total, run.initial_rate, run.rate,
                                                      run.accel)
                                         .Time(progress)
                                   : TrapezoidArrivalTime(progress, run.total, run.rate,
                                                          run.accel));
    }
    if (run_time > 0.0) a->runs.push_back(run);
    first = last;
  }
}

/// The duration of one rest-to-rest trapezoid over the whole path for each quantity (arc
/// length, yaw, every joint: total travel at its rate and acceleration limits), the longest:
/// the path driven without stopping at its vertices, a closer estimate of the optimized
/// duration than the rest-to-rest runs (which stop at every turn).
double ContinuousProfileDuration(const PathArrays& a, const BaseLimits& base,
                                 const JointLimits& joints, double fraction) {
  const int n = a.size(), num_joints = static_cast<int>(a.q.rows());
  double distance = 0.0, turn = 0.0;
  Eigen::VectorXd joint_travel = Eigen::VectorXd::Zero(num_joints);
  for (int k = 1; k < n; ++k) {
    distance += std::abs(a.s(k) - a.s(k - 1));
    turn += std::abs(a.yaw(k) - a.yaw(k - 1));
    joint_travel += (a.q.col(k) - a.q.col(k - 1)).cwiseAbs();
  }
  double duration = std::max(
      RunTime(distance, fraction * base.v_max_mps, fraction * base.a_max_mps2),
      RunTime(turn, fraction * base.omega_max_radps, fraction * base.beta_max_radps2));
  for (int j = 0; j < num_joints; ++j) {
    duration = std::max(duration, RunTime(joint_travel(j), fraction * joints.qd_max_radps(j),
                                          fraction * joints.qdd_max_radps2(j)));
  }
  return duration;
}

/// Linear interpolation of the path at time t: x, y, s, yaw, q into the outputs.
struct PathPoint {
  double x = 0.0, y = 0.0, s = 0.0, yaw = 0.0;
  Eigen::VectorXd q;
};

PathPoint Blend(const PathArrays& a, int k, int k1, double f) {
  PathPoint p;
  p.x = a.x(k) + f * (a.x(k1) - a.x(k));
  p.y = a.y(k) + f * (a.y(k1) - a.y(k));
  p.s = a.s(k) + f * (a.s(k1) - a.s(k));
  p.yaw = a.yaw(k) + f * (a.yaw(k1) - a.yaw(k));
  p.q = a.q.col(k) + f * (a.q.col(k1) - a.q.col(k));
  return p;
}

/// The path at time t: the run containing t, its trapezoid's travel at t, and the linear
/// blend of the two states whose progress brackets that travel.
PathPoint Interpolate(const PathArrays& a, double t) {
  for (const Run& run : a.runs) {
    if (t > run.start_s + run.duration_s) continue;
    const double travel =
        run.initial_rate > 0.0
            ? FromSpeedProfile(run.total, run.initial_rate, run.rate, run.accel)
                  .Travel(t - run.start_s)
            : TrapezoidTravel(t - run.start_s, run.total, run.rate, run.accel);
    int k = run.first;
    while (k + 1 < run.last && a.progress(k + 1) <= travel) ++k;
    const double span = a.progress(k + 1) - a.progress(k);
    const double f = span > 0.0 ? std::clamp((travel - a.progress(k)) / span, 0.0, 1.0) : 1.0;
    return Blend(a, k, k + 1, f);
  }
  return Blend(a, a.size() - 1, a.size() - 1, 0.0);  // after the last run: the end
}

void CheckInputs(const WholeBodyPath& path, const WholeBodyState& start, const BaseLimits& base,
                 const JointLimits& joints, int panels, const WarmStartOptions& options) {
  const int num_joints = start.num_joints();
  Require(!path.states.empty(), "the initial path has no states");
  Require(start.IsFinite(), "the start state is not finite");
  for (std::size_t k = 0; k < path.states.size(); ++k) {
    Require(path.states[k].num_joints() == num_joints,
            "path state " + std::to_string(k) + " has " +
                std::to_string(path.states[k].num_joints()) + " joints, the start " +
                std::to_string(num_joints));
    Require(path.states[k].IsFinite(), "path state " + std::to_string(k) + " is not finite");
  }
  for (double limit : {base.v_max_mps, base.a_max_mps2, base.omega_max_radps,
                       base.beta_max_radps2}) {
    Require(std::isfinite(limit) && limit > 0.0, "base limits must be finite and > 0");
  }
  Require(joints.qd_max_radps.size() == num_joints && joints.qdd_max_radps2.size() == num_joints,
          "joint rate limits are not sized for " + std::to_string(num_joints) + " joints");
  Require((joints.qd_max_radps.array() > 0.0).all() && (joints.qdd_max_radps2.array() > 0.0).all(),
          "joint rate limits must be > 0");
  Require(panels >= 1, "panels_per_piece must be >= 1");
  CheckWarmStartOptions(options);
  const WholeBodyState& first = path.states.front();
  const double offset_m = std::hypot(first.x_m - start.x_m, first.y_m - start.y_m);
  const double offset_rad = std::max(std::abs(WrapAngle(first.yaw_rad - start.yaw_rad)),
                                     (first.q_rad - start.q_rad).cwiseAbs().maxCoeff());
  Require(offset_m <= options.start_tolerance_m && offset_rad <= options.start_tolerance_rad,
          "the initial path begins " + std::to_string(offset_m) + " m / " +
              std::to_string(offset_rad) + " rad away from the start state");
}

}  // namespace

void CheckWarmStartOptions(const WarmStartOptions& options) {
  Require(options.piece_duration_s > 0.0, "piece_duration_s must be > 0");
  Require(options.min_pieces >= 1, "min_pieces must be >= 1");
  Require(options.max_pieces >= options.min_pieces, "max_pieces must be >= min_pieces");
  Require(options.rate_fraction > 0.0 && options.rate_fraction <= 1.0,
          "rate_fraction must be in (0, 1]");
  Require(options.min_duration_s > 0.0, "min_duration_s must be > 0");
}

WarmStart MakeWarmStart(const WholeBodyPath& path, const WholeBodyState& start,
                        const BaseLimits& base_limits, const JointLimits& joint_limits,
                        int panels_per_piece, const WarmStartOptions& options) {
  return MakeWarmStart(path, start, WholeBodyRates{}, base_limits, joint_limits,
                       panels_per_piece, options);
}

WarmStart MakeWarmStart(const WholeBodyPath& path, const WholeBodyState& start,
                        const WholeBodyRates& start_rates, const BaseLimits& base_limits,
                        const JointLimits& joint_limits, int panels_per_piece,
                        const WarmStartOptions& options) {
  CheckInputs(path, start, base_limits, joint_limits, panels_per_piece, options);
  Require(start_rates.IsFinite(), "the start rates are not finite");
  PathArrays arrays = ToArrays(path, start);
  TimeThePath(base_limits, joint_limits, options.rate_fraction, start_rates.v_mps, &arrays);
  const double profile_s = arrays.t(arrays.size() - 1);
  WarmStart warm;
  warm.path_arc_length_m = arrays.s;
  warm.path_times_s = arrays.t;
  warm.total_duration_s = std::max(profile_s, options.min_duration_s);
  warm.continuous_duration_s =
      std::max(ContinuousProfileDuration(arrays, base_limits, joint_limits, options.rate_fraction),
               options.min_duration_s);
  const int M = std::clamp(
      static_cast<int>(std::ceil(warm.continuous_duration_s / options.piece_duration_s)),
      options.min_pieces, options.max_pieces);
  const int D = 2 + start.num_joints(), K = panels_per_piece;
  const double T = warm.total_duration_s / M;
  // Times on the path's profile for a time on the warm start's (they differ only when the
  // profile is shorter than min_duration_s).
  const double scale = profile_s > 0.0 ? profile_s / warm.total_duration_s : 0.0;
  warm.num_pieces = M;
  warm.durations_s.setConstant(M, T);
  warm.waypoints.resize(D, M - 1);
  for (int i = 0; i + 1 < M; ++i) {
    const PathPoint p = Interpolate(arrays, scale * (i + 1) * T);
    warm.waypoints(0, i) = p.s;
    warm.waypoints(1, i) = p.yaw;
    warm.waypoints.col(i).tail(D - 2) = p.q;
  }
  const int last = arrays.size() - 1;
  warm.end.resize(D);
  warm.end(0) = arrays.s(last);
  warm.end(1) = arrays.yaw(last);
  warm.end.tail(D - 2) = arrays.q.col(last);
  const int samples = M * (K + 1);
  warm.reference.p_W.resize(2, samples);
  warm.reference.yaw_rad.resize(samples);
  warm.reference.q_rad.resize(D - 2, samples);
  for (int j = 0; j < M; ++j) {
    for (int l = 0; l <= K; ++l) {
      const PathPoint p = Interpolate(arrays, scale * (j + static_cast<double>(l) / K) * T);
      const int r = j * (K + 1) + l;
      warm.reference.p_W.col(r) = Eigen::Vector2d(p.x, p.y);
      warm.reference.yaw_rad(r) = p.yaw;
      warm.reference.q_rad.col(r) = p.q;
    }
  }
  return warm;
}

}  // namespace topay
