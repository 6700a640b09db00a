#include "core/optimization/flatness_optimizer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/common/stopwatch.h"
#include "core/optimization/lbfgs_solve.h"

namespace topay {
namespace {

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0,
                   double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c, d);
  return buffer;
}

}  // namespace

struct FlatnessOptimizer::Run {
  Run(const TrajectoryProblem& problem_in, std::stop_token stop_in)
      : problem(problem_in), stop(std::move(stop_in)) {}

  const TrajectoryProblem& problem;
  std::stop_token stop;
  Stopwatch watch;  ///< Since the start of Optimize.
  Stopwatch::Clock::time_point deadline;
  BackEndSummary summary;
  std::unique_ptr<FlatnessObjective> objective;
  Eigen::VectorXd x;
  bool aborted = false;  ///< Stopped or out of time inside an L-BFGS solve.

  BackEndSummary Finish(BackEndStatus status, const std::string& reason) {
    summary.status = status;
    summary.reason = reason;
    summary.total_s = watch.ElapsedS();
    summary.stage2_s = summary.total_s;
    return summary;
  }
};

FlatnessOptimizer::FlatnessOptimizer(const Kinematics& kinematics,
                                     const SignedDistanceField2& base_field,
                                     const SignedDistanceField3& arm_field,
                                     FlatnessOptimizerOptions options)
    : kinematics_(kinematics),
      base_field_(base_field),
      arm_field_(arm_field),
      options_(std::move(options)) {
  const FlatnessOptimizerOptions& o = options_;
  CheckBackEndOptions(o, "FlatnessOptimizerOptions");
  if (!(std::isfinite(o.check_period_s) && o.check_period_s > 0.0)) {
    throw std::invalid_argument("FlatnessOptimizerOptions: check_period_s must be finite and > 0");
  }
  SamplePenalties check(kinematics, base_field, arm_field, kinematics.model().base_limits,
                        o.objective.penalties);  // throws for bad penalty options
  reach_ = ComputeReachHeights(kinematics);
}

BackEndSummary FlatnessOptimizer::Optimize(const TrajectoryProblem& problem,
                                           const WholeBodyPath& initial_path,
                                           std::stop_token stop) const {
  Run run(problem, stop);
  run.deadline = DeadlineAfter(run.watch.start(), options_.time_limit_s);
  run.summary.parameterisation = TrajectoryParameterisation::kFlatness;
  if (stop.stop_requested()) return run.Finish(BackEndStatus::kCancelled, "cancelled");
  const std::string error = CheckTrajectoryProblem(problem, kinematics_, arm_field_, reach_);
  if (!error.empty()) return run.Finish(BackEndStatus::kInvalidInput, error);
  // The baseline's head is a rest state (its flat outputs x, y, yaw); it has no moving start.
  if (!problem.start_rates.IsAtRest()) {
    return run.Finish(BackEndStatus::kInvalidInput,
                      "moving start: the flatness baseline plans from rest only (use the arc "
                      "length-yaw back end)");
  }
  // Checked like the arc length-yaw back end's, but not used (see the class comment).
  const std::string stretch_error =
      CheckExactPathStretches(problem, static_cast<int>(initial_path.states.size()));
  if (!stretch_error.empty()) return run.Finish(BackEndStatus::kInvalidInput, stretch_error);
  if (!Prepare(initial_path, &run)) return run.summary;
  try {
    RunAugmentedLagrangian(&run);
    if (stop.stop_requested()) return run.Finish(BackEndStatus::kCancelled, "cancelled");
    Conclude(&run);
    return run.summary;
  } catch (const std::exception& e) {
    return run.Finish(BackEndStatus::kNotConverged, std::string("internal error: ") + e.what());
  }
}

bool FlatnessOptimizer::Prepare(const WholeBodyPath& initial_path, Run* run) const {
  const TrajectoryProblem& problem = run->problem;
  try {
    const int K = options_.objective.panels_per_piece;
    const WarmStart warm =
        MakeWarmStart(initial_path, problem.start, problem.base_limits,
                      kinematics_.model().joint_limits, K, options_.warm_start);
    const int M = warm.num_pieces, N = kinematics_.num_joints();
    run->objective = std::make_unique<FlatnessObjective>(
        kinematics_, base_field_, arm_field_, problem.base_limits, problem.start,
        problem.X_WE_goal, M, options_.objective);
    // Base positions at the piece ends from the path reference (sample (j, K)).
    Eigen::MatrixXd waypoints(N + 2, M - 1);
    for (int i = 0; i + 1 < M; ++i) {
      waypoints.col(i).head<2>() = warm.reference.p_W.col(i * (K + 1) + K);
      waypoints.col(i).tail(N) = warm.waypoints.col(i).tail(N);
    }
    Eigen::VectorXd end(N + 3);
    end.head<2>() = warm.reference.p_W.col(M * (K + 1) - 1);
    end(2) = warm.end(1);
    end.tail(N) = warm.end.tail(N);
    run->x = run->objective->Pack(warm.durations_s, waypoints, end);
  } catch (const std::invalid_argument& e) {
    run->Finish(BackEndStatus::kInvalidInput, std::string("initial path: ") + e.what());
    return false;
  }
  return true;
}

void FlatnessOptimizer::RunAugmentedLagrangian(Run* run) const {
  FlatnessObjective& objective = *run->objective;
  BackEndSummary& summary = run->summary;
  objective.set_stop_token(run->stop);
  Vector6d lambda = Vector6d::Zero();
  double rho = options_.alm.rho_initial;
  double cost = 0.0;
  for (int outer = 0; outer < options_.alm.max_outer_iterations && !run->aborted; ++outer) {
    objective.set_multiplier(lambda, rho);
    const LbfgsResult result =
        SolveWithLbfgs(&objective, &run->x, options_.lbfgs, run->deadline, run->stop);
    run->aborted = result.stop == LbfgsStop::kCancelled ||
                   result.stop == LbfgsStop::kTimeLimit || objective.stopped();
    summary.stage2_iterations += result.iterations;
    ++summary.outer_iterations;
    if (run->aborted || !objective.Evaluate(run->x.data(), &cost, nullptr)) break;
    const Vector6d r = objective.end_effector_residual();
    if (AlmConverged(options_.alm, r)) break;
    AlmUpdate(options_.alm, r, &lambda, &rho);  // PHR-ALM update, eq. (7)
  }
  summary.objective_evaluations = objective.num_evaluations();
}

void FlatnessOptimizer::Conclude(Run* run) const {
  FlatnessObjective& objective = *run->objective;
  BackEndSummary& summary = run->summary;
  objective.set_stop_token({});
  double cost = 0.0;
  if (!objective.Evaluate(run->x.data(), &cost, nullptr)) {
    run->Finish(BackEndStatus::kNotConverged,
                "the optimization diverged: the final objective is not finite (a zero "
                "speed inside the trajectory?)");
    return;
  }
  summary.flatness = objective.TrajectoryData();
  summary.num_pieces = summary.flatness.num_pieces();
  summary.durations_s = summary.flatness.durations_s;
  summary.duration_s = summary.flatness.duration_s();
  const FlatnessBreakdown& breakdown = objective.breakdown();
  summary.final_cost.jerk = breakdown.jerk;
  summary.final_cost.time = breakdown.time;
  summary.final_cost.end_effector = breakdown.end_effector;
  summary.final_cost.penalties = breakdown.penalties;
  summary.final_cost.total = breakdown.total;
  summary.final_min_speed_cost = breakdown.min_speed;
  summary.ee_position_error_m = objective.end_effector_residual().head<3>().norm();
  summary.ee_orientation_error_rad = objective.end_effector_residual().tail<3>().norm();
  Check(run->problem, &summary);
  std::string problems;
  if (summary.ee_position_error_m > options_.ee_position_tolerance_m ||
      summary.ee_orientation_error_rad > options_.ee_orientation_tolerance_rad) {
    problems = Format("end-effector error %.4f m / %.4f rad above %.3f m / %.3f rad",
                      summary.ee_position_error_m, summary.ee_orientation_error_rad,
                      options_.ee_position_tolerance_m, options_.ee_orientation_tolerance_rad);
  }
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    if (summary.check_violations[t] > 0.0) {
      problems += (problems.empty() ? "" : "; ") + std::string("violated: ") +
                  std::string(ToString(static_cast<PenaltyTerm>(t)));
    }
  }
  if (run->aborted && !problems.empty()) {
    problems = Format("time limit %.3f s reached; ", options_.time_limit_s) + problems;
  }
  run->Finish(problems.empty() ? BackEndStatus::kSuccess : BackEndStatus::kNotConverged,
              problems);
}

// Every check_period_s (and at the end): the sample penalties at the full rate limits with no
// joint margin; each term's worst value is recorded (> 0: violated).
void FlatnessOptimizer::Check(const TrajectoryProblem& problem,
                              BackEndSummary* summary) const {
  SamplePenaltyOptions options = options_.objective.penalties;
  options.rate_limit_fraction = 1.0;
  options.joint_position_margin_rad = 0.0;
  SamplePenalties penalties(kinematics_, base_field_, arm_field_, problem.base_limits, options);
  FlatnessTrajectory trajectory(summary->flatness);
  TrajectorySample sample = MakeTrajectorySample(trajectory.num_joints());
  SampleQuantities quantities = penalties.MakeQuantities();
  const double duration = trajectory.duration_s();
  const int count = static_cast<int>(std::ceil(duration / options_.check_period_s));
  summary->check_violations.fill(0.0);
  for (int i = 0; i <= count; ++i) {
    trajectory.Evaluate(std::min(i * options_.check_period_s, duration), &sample);
    quantities.x_m = sample.state.x_m;
    quantities.y_m = sample.state.y_m;
    quantities.yaw_rad = sample.state.yaw_rad;
    quantities.v_mps = sample.v_mps;
    quantities.a_mps2 = sample.a_mps2;
    quantities.omega_radps = sample.omega_radps;
    quantities.beta_radps2 = sample.beta_radps2;
    quantities.q_rad = sample.state.q_rad;
    quantities.qd_radps = sample.qd_radps;
    quantities.qdd_radps2 = sample.qdd_radps2;
    PenaltyValues costs{};
    penalties.Evaluate(quantities, nullptr, &costs);
    for (int t = 0; t < kNumPenaltyTerms; ++t) {
      summary->check_violations[t] = std::max(summary->check_violations[t], costs[t]);
    }
  }
}

}  // namespace topay
