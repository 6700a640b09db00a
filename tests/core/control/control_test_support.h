#pragma once
// Test support for tests/core/control: the TopAY robot's limits, synthetic references
// integrated from input profiles, and a closed loop with an ideal delayed unicycle +
// integrator plant.

#include <time.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "core/control/command_projection.h"
#include "core/control/control_command.h"
#include "core/control/latency_prediction.h"
#include "core/control/nmpc_solver.h"
#include "core/control/reference_horizon.h"
#include "core/control/tracker_limits.h"
#include "core/common/angles.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay::testing {

constexpr int kJoints = 7;

/// config/robot/topay_mm.yaml's limits.
inline TrackerLimits TopayLimits() {
  TrackerLimits limits;
  limits.base = BaseLimits{1.0, 0.8, 0.9, 1.0};
  limits.qd_max_radps = Eigen::VectorXd::Constant(kJoints, 2.35);
  limits.qdd_max_radps2 = Eigen::VectorXd::Constant(kJoints, 6.28);
  limits.coupled_v_omega = true;
  return limits;
}

/// Inputs of the reference at time t: v, omega, qd (N).
struct ReferenceInputs {
  double v_mps = 0.0;
  double omega_radps = 0.0;
  Eigen::VectorXd qd_radps = Eigen::VectorXd::Zero(kJoints);
};
using InputProfile = std::function<ReferenceInputs(double t_s)>;

/// A reference integrated from an input profile at 1 ms from start (x, y, yaw, q), sampled
/// by the nearest integration step (rates of the profile itself).
class SyntheticReference {
 public:
  SyntheticReference(const InputProfile& profile, double duration_s, const WholeBodyState& start)
      : duration_s_(duration_s) {
    const int n = static_cast<int>(std::ceil(duration_s / kDt)) + 1;
    WholeBodyState state = start;
    for (int i = 0; i < n; ++i) {
      const double t = i * kDt;
      const ReferenceInputs in = profile(t);
      TrajectorySample sample = MakeTrajectorySample(kJoints);
      sample.t_s = t;
      sample.state = state;
      sample.v_mps = in.v_mps;
      sample.omega_radps = in.omega_radps;
      sample.qd_radps = in.qd_radps;
      samples_.push_back(sample);
      const double theta = state.yaw_rad + 0.5 * in.omega_radps * kDt;
      state.x_m += in.v_mps * kDt * std::cos(theta);
      state.y_m += in.v_mps * kDt * std::sin(theta);
      state.yaw_rad += in.omega_radps * kDt;
      state.q_rad += kDt * in.qd_radps;
    }
  }

  double duration_s() const { return duration_s_; }
  const TrajectorySample& At(double t_s) const {
    const int i = std::clamp(static_cast<int>(std::lround(t_s / kDt)), 0,
                             static_cast<int>(samples_.size()) - 1);
    return samples_[i];
  }
  TrajectorySampler Sampler() const {
    return [this](double t_s, TrajectorySample* out) { *out = At(t_s); };
  }

 private:
  static constexpr double kDt = 0.001;
  double duration_s_;
  std::vector<TrajectorySample> samples_;
};

/// Trapezoid of peak `peak` reached at `rate` from t0, held, back to 0 ending at t1.
inline double Trapezoid(double t, double t0, double t1, double peak, double rate) {
  if (t <= t0 || t >= t1) return 0.0;
  const double ramp = std::abs(peak) / rate;
  const double up = std::min(1.0, (t - t0) / ramp);
  const double down = std::min(1.0, (t1 - t) / ramp);
  return peak * std::min(up, down);
}

inline WholeBodyState StateAt(double x, double y, double yaw, double q) {
  WholeBodyState state;
  state.x_m = x;
  state.y_m = y;
  state.yaw_rad = yaw;
  state.q_rad = Eigen::VectorXd::Constant(kJoints, q);
  return state;
}

/// Tracking errors of a state against a reference sample.
struct Errors {
  double position_m = 0.0;
  double yaw_rad = 0.0;
  double joint_rad = 0.0;
};

inline Errors ErrorsOf(const WholeBodyState& state, const TrajectorySample& ref) {
  Errors e;
  e.position_m = std::hypot(state.x_m - ref.state.x_m, state.y_m - ref.state.y_m);
  e.yaw_rad = std::abs(WrapAngle(state.yaw_rad - ref.state.yaw_rad));
  e.joint_rad = (state.q_rad - ref.state.q_rad).cwiseAbs().maxCoeff();
  return e;
}

/// A closed loop: every control period the solver is given the measured state predicted
/// over the latency (PredictState with the commands sent), the reference from then on, and
/// the last command; the plant is an ideal unicycle + integrators that applies each command
/// latency_s after it was sent (the same PredictState on the true state).
struct ClosedLoopResult {
  Errors final_errors;          ///< At the end of the run.
  Errors max_errors_last_half;  ///< Largest over the second half of the run.
  double worst_limit_ratio = 0.0;  ///< Over every returned sequence (<= 1: feasible).
  std::vector<ControlCommand> commands;
  int fallbacks = 0;
};

inline double ThreadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec;
}

/// solve_ms (optional): every solve's NmpcSummary::solve_ms (wall clock) appended;
/// solve_cpu_ms (optional): every solve's thread CPU time.
inline ClosedLoopResult RunClosedLoop(NmpcSolver* solver, const SyntheticReference& reference,
                                      WholeBodyState state, double run_s,
                                      std::vector<double>* solve_ms = nullptr,
                                      std::vector<double>* solve_cpu_ms = nullptr) {
  const NmpcOptions& options = solver->options();
  const double period = options.control_period_s;
  ReferenceHorizon horizon = ReferenceHorizon::Zero(options.horizon_steps, kJoints);
  TrajectorySample scratch = MakeTrajectorySample(kJoints);
  CommandHistory history(64, kJoints);
  ControlCommand last = ControlCommand::Zero(kJoints);
  ClosedLoopResult result;
  const int cycles = static_cast<int>(std::lround(run_s / period));
  for (int i = 0; i < cycles; ++i) {
    const double t = i * period;
    WholeBodyState predicted = state;
    PredictState(history, options.latency_s, t, t + options.latency_s, &predicted);
    SampleReferenceHorizon(reference.Sampler(), reference.duration_s(), t + options.latency_s,
                           options.step_s, &scratch, &horizon);
    const double cpu_start_ms = ThreadCpuMs();
    const InputSequence& inputs = solver->Solve(predicted, horizon, last);
    if (solve_cpu_ms != nullptr) solve_cpu_ms->push_back(ThreadCpuMs() - cpu_start_ms);
    result.worst_limit_ratio =
        std::max(result.worst_limit_ratio,
                 WorstInputLimitRatio(last, period, options.step_s, solver->limits(), inputs));
    result.fallbacks += solver->summary().fell_back;
    if (solve_ms != nullptr) solve_ms->push_back(solver->summary().solve_ms);
    inputs.CommandAt(0, &last);
    result.commands.push_back(last);
    history.Push(t, last);
    PredictState(history, options.latency_s, t, t + period, &state);  // the plant
    const Errors e = ErrorsOf(state, reference.At(t + period));
    if (i >= cycles / 2) {
      result.max_errors_last_half.position_m =
          std::max(result.max_errors_last_half.position_m, e.position_m);
      result.max_errors_last_half.yaw_rad = std::max(result.max_errors_last_half.yaw_rad, e.yaw_rad);
      result.max_errors_last_half.joint_rad =
          std::max(result.max_errors_last_half.joint_rad, e.joint_rad);
    }
    result.final_errors = e;
  }
  return result;
}

}  // namespace topay::testing
