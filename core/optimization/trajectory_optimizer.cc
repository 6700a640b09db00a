#include "core/optimization/trajectory_optimizer.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/stopwatch.h"

namespace topay {
namespace {

using Clock = Stopwatch::Clock;

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c, d);
  return buffer;
}

/// Stage 1's terms (the authors' code): jerk, time, path fit and the kinodynamic penalties.
ObjectiveTerms Stage1Terms() {
  ObjectiveTerms terms;
  terms.end_effector = false;
  terms.path_fit = true;
  terms.penalties = NoPenalties();
  for (PenaltyTerm term : {PenaltyTerm::kVelocityOmega, PenaltyTerm::kAcceleration,
                           PenaltyTerm::kYawAcceleration, PenaltyTerm::kJointPosition,
                           PenaltyTerm::kJointVelocity, PenaltyTerm::kJointAcceleration}) {
    terms.penalties[static_cast<int>(term)] = true;
  }
  return terms;
}

/// Multiplies the scales of the penalty terms whose hard constraints the report finds
/// violated by `factor`: a clearance its obstacle / self / chassis term, a rate limit all the
/// rate terms (the report keeps only the worst rate), a joint position its term.
void EscalateViolatedPenalties(const FieldFeasibilityReport& report,
                               const FieldFeasibilityOptions& options, double factor,
                               PenaltyValues* scales) {
  const auto raise = [&](PenaltyTerm term) { (*scales)[static_cast<int>(term)] *= factor; };
  if (report.min_base_clearance_m < 0.0) raise(PenaltyTerm::kBaseObstacle);
  if (report.min_arm_clearance_m < 0.0) raise(PenaltyTerm::kArmObstacle);
  if (report.min_self_clearance_m < 0.0) raise(PenaltyTerm::kSelfCollision);
  if (report.min_chassis_clearance_m < 0.0) raise(PenaltyTerm::kChassis);
  if (report.max_joint_excess_rad > options.joint_position_tolerance_rad) {
    raise(PenaltyTerm::kJointPosition);
  }
  if (report.max_rate_ratio > 1.0 + options.rate_tolerance) {
    for (PenaltyTerm term : {PenaltyTerm::kVelocityOmega, PenaltyTerm::kAcceleration,
                             PenaltyTerm::kYawAcceleration, PenaltyTerm::kJointVelocity,
                             PenaltyTerm::kJointAcceleration}) {
      raise(term);
    }
  }
}

/// A hard limit violated between two samples (the samples themselves may all be clear, so a
/// larger weight alone does not help): moves that threshold past the shortfall and a step
/// more. Clearances grow by shortfall + clearance_escalation_step_m, the joint margin by
/// excess + joint_escalation_step_rad, the rate limits shrink by 1 / ratio x (1 -
/// rate_escalation_step).
void TightenViolatedThresholds(const FieldFeasibilityReport& report,
                               const TrajectoryOptimizerOptions& options,
                               PenaltyTightening* tightening) {
  if (report.min_base_clearance_m < 0.0) {
    tightening->base_m += options.clearance_escalation_step_m - report.min_base_clearance_m;
  }
  if (report.min_arm_clearance_m < 0.0) {
    tightening->arm_m += options.clearance_escalation_step_m - report.min_arm_clearance_m;
  }
  if (report.max_joint_excess_rad > options.feasibility.joint_position_tolerance_rad) {
    tightening->joint_rad += options.joint_escalation_step_rad + report.max_joint_excess_rad;
  }
  if (report.max_rate_ratio > 1.0 + options.feasibility.rate_tolerance) {
    tightening->rate_scale *= (1.0 - options.rate_escalation_step) / report.max_rate_ratio;
  }
}

/// True if the report's only violations are rate limits (every clearance and joint position
/// within its requirement, some rate above its tolerance).
bool OnlyRatesViolated(const FieldFeasibilityReport& report,
                       const FieldFeasibilityOptions& options) {
  return report.min_base_clearance_m >= 0.0 && report.min_arm_clearance_m >= 0.0 &&
         report.min_self_clearance_m >= 0.0 && report.min_chassis_clearance_m >= 0.0 &&
         report.max_joint_excess_rad <= options.joint_position_tolerance_rad &&
         report.max_rate_ratio > 1.0 + options.rate_tolerance;
}

/// True for the rates that scale with 1 / k^2 under a time stretch by k (a, beta, qdd<i>).
bool IsAccelerationRate(const std::string& name) {
  return name == "a" || name == "beta" || name.rfind("qdd", 0) == 0;
}

}  // namespace

void CheckTrajectoryOptimizerOptions(const TrajectoryOptimizerOptions& o) {
  const auto require = [](bool ok, const char* name) {
    if (!ok) throw std::invalid_argument(std::string("TrajectoryOptimizerOptions: ") + name);
  };
  require(o.stage1_max_iterations >= 0, "stage1_max_iterations must be >= 0");
  require(o.max_penalty_escalations >= 0, "max_penalty_escalations must be >= 0");
  require(o.penalty_escalation_factor >= 1.0, "penalty_escalation_factor must be >= 1");
  require(std::isfinite(o.clearance_escalation_step_m) && o.clearance_escalation_step_m >= 0.0,
          "clearance_escalation_step_m must be finite and >= 0");
  require(std::isfinite(o.joint_escalation_step_rad) && o.joint_escalation_step_rad >= 0.0,
          "joint_escalation_step_rad must be finite and >= 0");
  require(o.rate_escalation_step >= 0.0 && o.rate_escalation_step < 1.0,
          "rate_escalation_step must be in [0, 1)");
  require(std::isfinite(o.max_time_stretch) && o.max_time_stretch >= 1.0,
          "max_time_stretch must be finite and >= 1");
  require(std::isfinite(o.collapse_duration_fraction) && o.collapse_duration_fraction >= 0.0 &&
              o.collapse_duration_fraction < 1.0,
          "collapse_duration_fraction must be in [0, 1)");
  require(std::isfinite(o.collapse_rho_factor) && o.collapse_rho_factor > 1.0,
          "collapse_rho_factor must be finite and > 1");
  require(o.max_collapse_restarts >= 0, "max_collapse_restarts must be >= 0");
  require(o.objective.panels_per_piece >= 1, "objective.panels_per_piece must be >= 1");
  require(o.objective.sample_chunks >= 1, "objective.sample_chunks must be >= 1");
  require(o.feasibility.sample_period_s > 0.0, "feasibility.sample_period_s must be > 0");
  require(o.feasibility.rate_tolerance >= 0.0, "feasibility.rate_tolerance must be >= 0");
  require(std::isfinite(o.endpoint_relief.slack_m) && o.endpoint_relief.slack_m >= 0.0,
          "endpoint_relief.slack_m must be finite and >= 0");
  require(std::isfinite(o.objective.time_weight) && o.objective.time_weight >= 0.0,
          "objective.time_weight must be finite and >= 0");
  const auto finite_nonnegative = [](double x) { return std::isfinite(x) && x >= 0.0; };
  require(finite_nonnegative(o.objective.path_fit_position_weight),
          "objective.path_fit_position_weight must be finite and >= 0");
  require(finite_nonnegative(o.objective.path_fit_angle_weight),
          "objective.path_fit_angle_weight must be finite and >= 0");
  require(finite_nonnegative(o.objective.jerk_weights.arc_length),
          "objective.jerk_weights.arc_length must be finite and >= 0");
  require(finite_nonnegative(o.objective.jerk_weights.yaw),
          "objective.jerk_weights.yaw must be finite and >= 0");
  require(finite_nonnegative(o.objective.jerk_weights.joint),
          "objective.jerk_weights.joint must be finite and >= 0");
  CheckBackEndOptions(o, "TrajectoryOptimizerOptions");
}

struct TrajectoryOptimizer::Run {
  Run(const TrajectoryProblem& problem_in, std::stop_token stop_in)
      : problem(problem_in), stop(std::move(stop_in)) {}

  const TrajectoryProblem& problem;
  std::stop_token stop;
  Stopwatch watch;  ///< Since the start of Optimize.
  Clock::time_point deadline;
  BackEndSummary summary;
  WarmStart warm;
  EndpointRelief relief;  ///< Empty: none (the objective and the check then have none).
  std::unique_ptr<TrajectoryObjective> objective;
  Eigen::VectorXd x;
  bool cancelled = false;
  bool timed_out = false;
  bool checked = false;  ///< summary's trajectory and check are those of x.

  /// Records an inner solve's outcome; false if the run must stop (cancel, time limit).
  bool Account(const LbfgsResult& result, int* iterations) {
    *iterations += result.iterations;
    summary.objective_evaluations += result.evaluations;
    if (result.stop == LbfgsStop::kCancelled) cancelled = true;
    if (result.stop == LbfgsStop::kTimeLimit) timed_out = true;
    return !cancelled && !timed_out;
  }
  /// Ends the run with `status` and `reason`; the summary as it stands.
  BackEndSummary Fail(BackEndStatus status, const std::string& reason) {
    summary.status = status;
    summary.reason = reason;
    summary.total_s = watch.ElapsedS();
    return summary;
  }
};

TrajectoryOptimizer::TrajectoryOptimizer(const Kinematics& kinematics,
                                         const SignedDistanceField2& base_field,
                                         const SignedDistanceField3& arm_field,
                                         TrajectoryOptimizerOptions options)
    : kinematics_(kinematics),
      base_field_(base_field),
      arm_field_(arm_field),
      options_(std::move(options)) {
  CheckTrajectoryOptimizerOptions(options_);
  if (options_.parameterisation != TrajectoryParameterisation::kArcLengthYaw) {
    throw std::invalid_argument(
        "TrajectoryOptimizer: parameterisation is not arc length-yaw (build the flatness "
        "baseline with MakeTrajectoryBackEnd)");
  }
  // The penalty options (weights, margins, factors) are checked by building the penalties
  // once, with the model's own base limits.
  SamplePenalties check(kinematics, base_field, arm_field, kinematics.model().base_limits,
                        options_.objective.penalties);
  reach_ = ComputeReachHeights(kinematics);
}

BackEndSummary TrajectoryOptimizer::Optimize(const TrajectoryProblem& problem,
                                             const WholeBodyPath& initial_path,
                                             std::stop_token stop) const {
  Run run(problem, stop);
  run.deadline = DeadlineAfter(run.watch.start(), options_.time_limit_s);
  run.summary.panels_per_piece = options_.objective.panels_per_piece;
  if (stop.stop_requested()) return run.Fail(BackEndStatus::kCancelled, "cancelled");
  const std::string problem_error =
      CheckTrajectoryProblem(problem, kinematics_, arm_field_, reach_);
  if (!problem_error.empty()) return run.Fail(BackEndStatus::kInvalidInput, problem_error);
  const std::string stretch_error =
      CheckExactPathStretches(problem, static_cast<int>(initial_path.states.size()));
  if (!stretch_error.empty()) return run.Fail(BackEndStatus::kInvalidInput, stretch_error);
  if (!Prepare(initial_path, &run)) return run.summary;
  run.summary.warm_start_s = run.watch.ElapsedS();
  try {
    RunStages(&run);
    Finish(&run);
  } catch (const std::exception& e) {  // not expected: a bug, reported rather than thrown
    return run.Fail(BackEndStatus::kNotConverged, std::string("internal error: ") + e.what());
  }
  run.summary.total_s = run.watch.ElapsedS();
  return run.summary;
}

bool TrajectoryOptimizer::Prepare(const WholeBodyPath& initial_path, Run* run) const {
  const TrajectoryProblem& problem = run->problem;
  try {
    run->warm = MakeWarmStart(initial_path, problem.start, problem.start_rates,
                              problem.base_limits, kinematics_.model().joint_limits,
                              options_.objective.panels_per_piece, options_.warm_start);
    run->objective = std::make_unique<TrajectoryObjective>(
        kinematics_, base_field_, arm_field_, problem.base_limits, problem.start,
        problem.X_WE_goal, run->warm.num_pieces, options_.objective);
    run->objective->set_start_rates(problem.start_rates);  // the head: C2 with the start
    run->x = run->objective->Pack(run->warm.durations_s, run->warm.waypoints, run->warm.end);
    PrepareEndpointRelief(initial_path, run);
  } catch (const std::invalid_argument& e) {
    run->Fail(BackEndStatus::kInvalidInput, std::string("initial path: ") + e.what());
    return false;
  }
  return true;
}

void TrajectoryOptimizer::PrepareEndpointRelief(const WholeBodyPath& initial_path,
                                                Run* run) const {
  const TrajectoryProblem& problem = run->problem;
  if (problem.exact_prefix_states == 0 && problem.exact_suffix_states == 0) return;
  // The thresholds the objective's penalties compare against.
  const SamplePenalties penalties(kinematics_, base_field_, arm_field_, problem.base_limits,
                                  options_.objective.penalties);
  // The deficits along the path's exactly validated stretches (its first state is the start
  // itself, its last the goal).
  run->relief = MakeEndpointRelief(penalties, problem.start, initial_path.states,
                                   run->warm.path_times_s,
                                   run->warm.num_pieces, problem.exact_prefix_states,
                                   problem.exact_suffix_states, options_.endpoint_relief);
  if (run->relief.empty()) return;
  run->objective->set_endpoint_relief(&run->relief);
  run->summary.endpoint_relief = run->relief.Describe();
}

// Stage 1 then stage 2; both again from the warm start with a larger rho while stage 2's
// duration collapsed.
void TrajectoryOptimizer::RunStages(Run* run) const {
  run->objective->set_stop_token(run->stop);
  double rho = options_.alm.rho_initial;
  for (int restart = 0;; ++restart) {
    if (options_.run_stage1 && options_.stage1_max_iterations > 0 && !RunStage1(run)) return;
    if (RunStage2(rho, run) || restart == options_.max_collapse_restarts ||
        !DurationCollapsed(*run)) {
      return;
    }
    rho = std::min(rho * options_.collapse_rho_factor, options_.alm.rho_max);
    run->x = run->objective->Pack(run->warm.durations_s, run->warm.waypoints, run->warm.end);
    ++run->summary.collapse_restarts;
  }
}

bool TrajectoryOptimizer::RunStage1(Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  const Stopwatch stage;
  objective.set_terms(Stage1Terms());
  objective.set_path_reference(run->warm.reference);
  LbfgsOptions lbfgs = options_.lbfgs;
  lbfgs.max_iterations = options_.stage1_max_iterations;
  const LbfgsResult result = SolveWithLbfgs(&objective, &run->x, lbfgs, run->deadline, run->stop);
  const bool go_on = run->Account(result, &run->summary.stage1_iterations);
  run->summary.stage1_s += stage.ElapsedS();
  return go_on;
}

// Stage 2: PHR-ALM on eq. (7) with every other term; while the result is infeasible on the
// fields, the penalty weights are raised and the ALM continues from where it was.
bool TrajectoryOptimizer::RunStage2(double rho, Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  BackEndSummary& summary = run->summary;
  const Stopwatch stage;
  const auto done = [&](bool success) {
    summary.stage2_s += stage.ElapsedS();
    return success;
  };
  objective.set_terms(ObjectiveTerms());
  Vector6d lambda = Vector6d::Zero();
  PenaltyValues scales = OnesPenaltyValues();
  PenaltyTightening tightening;
  objective.set_penalty_scales(scales);
  objective.set_tightening(tightening);
  for (int escalation = 0;; ++escalation) {
    if (!RunAugmentedLagrangian(run, &lambda, &rho)) return done(false);
    if (CheckResult(run)) return done(true);  // success
    if (StretchTime(run)) return done(true);  // success, slower
    if (summary.feasibility.feasible || escalation == options_.max_penalty_escalations) {
      return done(false);
    }
    const FieldFeasibilityReport& report = summary.feasibility;
    EscalateViolatedPenalties(report, options_.feasibility, options_.penalty_escalation_factor,
                              &scales);
    objective.set_penalty_scales(scales);
    TightenViolatedThresholds(report, options_, &tightening);
    objective.set_tightening(tightening);
    ++summary.penalty_escalations;
  }
}

bool TrajectoryOptimizer::DurationCollapsed(const Run& run) const {
  const BackEndSummary& summary = run.summary;
  if (run.cancelled || run.timed_out || !run.checked) return false;
  const bool on_target = summary.ee_position_error_m <= options_.ee_position_tolerance_m &&
                         summary.ee_orientation_error_rad <= options_.ee_orientation_tolerance_rad;
  return !on_target &&
         summary.duration_s < options_.collapse_duration_fraction * run.warm.total_duration_s;
}

bool TrajectoryOptimizer::RunAugmentedLagrangian(Run* run, Vector6d* lambda, double* rho) const {
  TrajectoryObjective& objective = *run->objective;
  BackEndSummary& summary = run->summary;
  for (int outer = 0; outer < options_.alm.max_outer_iterations; ++outer) {
    objective.set_multiplier(*lambda, *rho);
    const LbfgsResult result =
        SolveWithLbfgs(&objective, &run->x, options_.lbfgs, run->deadline, run->stop);
    ++summary.outer_iterations;
    summary.final_rho = *rho;
    if (!run->Account(result, &summary.stage2_iterations)) return false;
    double cost = 0.0;
    ++summary.objective_evaluations;
    if (!objective.Evaluate(run->x.data(), &cost, nullptr)) return true;  // Finish reports it
    const Vector6d r = objective.end_effector_residual();
    if (AlmConverged(options_.alm, r)) return true;
    AlmUpdate(options_.alm, r, lambda, rho);  // PHR-ALM update, eq. (7)
  }
  return true;
}

bool TrajectoryOptimizer::StretchTime(Run* run) const {
  constexpr int kMaxSteps = 4;
  BackEndSummary& summary = run->summary;
  const FieldFeasibilityOptions& check = options_.feasibility;
  if (!run->checked || options_.max_time_stretch <= 1.0 ||
      !run->problem.start_rates.IsAtRest() || !OnlyRatesViolated(summary.feasibility, check) ||
      summary.ee_position_error_m > options_.ee_position_tolerance_m ||
      summary.ee_orientation_error_rad > options_.ee_orientation_tolerance_rad) {
    return false;
  }
  TrajectoryObjective& objective = *run->objective;
  const Eigen::VectorXd x_before = run->x;
  const BackEndSummary summary_before = summary;  // its trajectory and check are x_before's
  Eigen::VectorXd durations_s;
  Eigen::MatrixXd waypoints;
  Eigen::VectorXd end;
  objective.Unpack(run->x.data(), &durations_s, &waypoints, &end);
  const double target = 1.0 - options_.rate_escalation_step;
  double total = 1.0;
  for (int step = 0; step < kMaxSteps && OnlyRatesViolated(summary.feasibility, check); ++step) {
    const double ratio = summary.feasibility.max_rate_ratio / target;
    // Velocities fall by 1 / k, accelerations by 1 / k^2.
    const double k = IsAccelerationRate(summary.feasibility.worst_rate) ? std::sqrt(ratio) : ratio;
    if (total * k > options_.max_time_stretch) break;
    total *= k;
    durations_s *= k;
    run->x = objective.Pack(durations_s, waypoints, end);
    if (CheckResult(run)) {
      summary.time_stretch = total;
      return true;
    }
  }
  // The unstretched result and its check, as the caller had them (restored, not recomputed:
  // the summary holds all that is read of a checked run).
  const int evaluations = summary.objective_evaluations;  // the attempts' work still counts
  const double check_s = summary.check_s;
  run->x = x_before;
  summary = summary_before;
  summary.objective_evaluations = evaluations;
  summary.check_s = check_s;
  run->checked = true;
  return false;
}

bool TrajectoryOptimizer::CopyTrajectory(Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  BackEndSummary& summary = run->summary;
  double cost = 0.0;
  ++summary.objective_evaluations;
  if (!objective.Evaluate(run->x.data(), &cost, nullptr)) return false;
  summary.num_pieces = objective.num_pieces();
  summary.p0_W = objective.p0_W();
  summary.head = objective.head();
  summary.tail = objective.tail();
  summary.waypoints = objective.waypoints();
  summary.durations_s = objective.durations_s();
  summary.duration_s = objective.durations_s().sum();
  return true;
}

bool TrajectoryOptimizer::CheckResult(Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  BackEndSummary& summary = run->summary;
  const Stopwatch check;
  run->checked = false;
  if (!CopyTrajectory(run)) return false;
  summary.final_cost = objective.breakdown();
  const Vector6d& r = objective.end_effector_residual();
  summary.ee_position_error_m = r.head<3>().norm();
  summary.ee_orientation_error_rad = r.tail<3>().norm();
  summary.feasibility = CheckFeasibilityOnFields(
      objective.trajectory(), kinematics_, base_field_, arm_field_, run->problem.base_limits,
      options_.feasibility, run->relief.empty() ? nullptr : &run->relief);
  summary.check_s += check.ElapsedS();
  run->checked = true;
  return summary.feasibility.feasible &&
         summary.ee_position_error_m <= options_.ee_position_tolerance_m &&
         summary.ee_orientation_error_rad <= options_.ee_orientation_tolerance_rad;
}

void TrajectoryOptimizer::Finish(Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  BackEndSummary& summary = run->summary;
  objective.set_stop_token({});  // the final evaluation must run even after a cancel
  objective.set_terms(ObjectiveTerms());
  if (run->cancelled) {
    // The last iterate's trajectory, without the check: a cancel must return promptly.
    summary.status = BackEndStatus::kCancelled;
    summary.reason = "cancelled";
    CopyTrajectory(run);
    return;
  }
  if (!run->checked) CheckResult(run);
  if (!run->checked) {
    summary.status = BackEndStatus::kNotConverged;
    summary.reason = "the optimization diverged: the final objective is not finite";
    return;
  }
  if (run->timed_out) StretchTime(run);  // RunStage2 stopped before trying it
  Conclude(run);
}

void TrajectoryOptimizer::Conclude(Run* run) const {
  BackEndSummary& summary = run->summary;
  std::vector<std::string> problems;
  if (summary.ee_position_error_m > options_.ee_position_tolerance_m ||
      summary.ee_orientation_error_rad > options_.ee_orientation_tolerance_rad) {
    problems.push_back(Format("end-effector error %.4f m / %.4f rad above %.3f m / %.3f rad",
                              summary.ee_position_error_m, summary.ee_orientation_error_rad,
                              options_.ee_position_tolerance_m,
                              options_.ee_orientation_tolerance_rad));
  }
  if (!summary.feasibility.feasible) {
    problems.push_back("infeasible on the fields: " +
                       DescribeViolations(summary.feasibility, options_.feasibility) +
                       " (first: " + summary.feasibility.first_violation + ")");
  }
  // A run cut short by the time limit still succeeds if its last iterate passes.
  if (problems.empty()) {
    summary.status = BackEndStatus::kSuccess;
    summary.reason.clear();
    return;
  }
  if (run->timed_out) {
    problems.insert(problems.begin(), Format("time limit %.3f s reached", options_.time_limit_s));
  }
  summary.status = BackEndStatus::kNotConverged;
  summary.reason.clear();
  for (const std::string& p : problems) {
    summary.reason += (summary.reason.empty() ? "" : "; ") + p;
  }
}

}  // namespace topay
