#include "core/optimization/trajectory_optimizer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/optimization/flatness_optimizer.h"
#include "core/trajectory/arc_yaw_sampling.h"

namespace topay {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c, d);
  return buffer;
}

/// Stage 1's terms (facts sheet): jerk, time, path fit and the kinodynamic penalties.
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

/// Heights (world z) the end-effector origin can reach: the first movable joint of E's chain
/// stays at a fixed height over the base; from it, E is at most the sum of the chain's fixed
/// offsets away (triangle inequality).
void ReachHeights(const Kinematics& kinematics, double* min_z, double* max_z) {
  const RobotModel& model = kinematics.model();
  std::vector<int> chain;  // E's link up to the root
  for (int link = model.end_effector_link; link >= 0; link = model.links[link].parent) {
    chain.push_back(link);
  }
  int first_joint = -1;  // the movable joint nearest the root
  for (int i = static_cast<int>(chain.size()) - 1; i >= 0; --i) {
    if (model.links[chain[i]].joint_type != JointType::kFixed) {
      first_joint = i;
      break;
    }
  }
  KinematicsCache cache = kinematics.MakeCache();
  WholeBodyState zero;
  zero.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  kinematics.Update(zero, &cache);
  if (first_joint < 0) {  // no arm: E is rigid on the base
    *min_z = *max_z = cache.X_WE.translation().z();
    return;
  }
  const double joint_z = cache.X_WL[chain[first_joint]].translation().z();
  double length = model.X_LE.translation().norm();
  for (int i = 0; i < first_joint; ++i) length += model.links[chain[i]].X_PJ.translation().norm();
  *min_z = joint_z - length;
  *max_z = joint_z + length;
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

/// The flatness baseline's options from the driver's (the shared parts; its own sampling and
/// minimum-speed defaults stay).
FlatnessOptimizerOptions FlatnessOptionsFrom(const TrajectoryOptimizerOptions& o) {
  FlatnessOptimizerOptions f;
  f.objective.jerk_weights = o.objective.jerk_weights;
  f.objective.time_weight = o.objective.time_weight;
  f.objective.penalties = o.objective.penalties;
  f.warm_start = o.warm_start;
  f.lbfgs = o.lbfgs;
  f.alm_rho_initial = o.alm_rho_initial;
  f.alm_rho_growth = o.alm_rho_growth;
  f.alm_rho_max = o.alm_rho_max;
  f.alm_max_outer_iterations = o.alm_max_outer_iterations;
  f.alm_position_tolerance_m = o.alm_position_tolerance_m;
  f.alm_orientation_tolerance_rad = o.alm_orientation_tolerance_rad;
  f.ee_position_tolerance_m = o.ee_position_tolerance_m;
  f.ee_orientation_tolerance_rad = o.ee_orientation_tolerance_rad;
  f.check_period_s = o.feasibility.sample_period_s;
  f.time_limit_s = o.time_limit_s;
  return f;
}

void CopyFlatnessSummary(const FlatnessOptimizerSummary& f, TrajectoryOptimizerSummary* s) {
  s->parameterisation = TrajectoryParameterisation::kFlatness;
  s->status = f.status;
  s->reason = f.reason;
  s->num_pieces = f.num_pieces;
  s->flatness = f.trajectory;
  s->durations_s = f.trajectory.durations_s;
  s->duration_s = f.duration_s;
  s->ee_position_error_m = f.ee_position_error_m;
  s->ee_orientation_error_rad = f.ee_orientation_error_rad;
  s->outer_iterations = f.outer_iterations;
  s->stage2_iterations = f.iterations;
  s->objective_evaluations = f.objective_evaluations;
  s->total_s = f.total_s;
  s->stage2_s = f.total_s;
  s->final_cost.jerk = f.final_cost.jerk;
  s->final_cost.time = f.final_cost.time;
  s->final_cost.end_effector = f.final_cost.end_effector;
  s->final_cost.penalties = f.final_cost.penalties;
  s->final_cost.total = f.final_cost.total;
}

}  // namespace

void CheckTrajectoryOptimizerOptions(const TrajectoryOptimizerOptions& o) {
  const auto require = [](bool ok, const char* name) {
    if (!ok) throw std::invalid_argument(std::string("TrajectoryOptimizerOptions: ") + name);
  };
  require(o.stage1_max_iterations >= 0, "stage1_max_iterations must be >= 0");
  require(std::isfinite(o.alm_rho_initial) && o.alm_rho_initial > 0.0,
          "alm_rho_initial must be finite and > 0");
  require(o.alm_rho_growth >= 1.0, "alm_rho_growth must be >= 1");
  require(o.alm_rho_max >= o.alm_rho_initial, "alm_rho_max must be >= alm_rho_initial");
  require(o.alm_max_outer_iterations >= 1, "alm_max_outer_iterations must be >= 1");
  require(o.alm_position_tolerance_m > 0.0 && o.alm_orientation_tolerance_rad > 0.0,
          "ALM tolerances must be > 0");
  require(o.ee_position_tolerance_m > 0.0 && o.ee_orientation_tolerance_rad > 0.0,
          "end-effector tolerances must be > 0");
  require(o.time_limit_s > 0.0, "time_limit_s must be > 0");
  require(o.max_penalty_escalations >= 0, "max_penalty_escalations must be >= 0");
  require(o.penalty_escalation_factor >= 1.0, "penalty_escalation_factor must be >= 1");
  require(std::isfinite(o.clearance_escalation_step_m) && o.clearance_escalation_step_m >= 0.0,
          "clearance_escalation_step_m must be finite and >= 0");
  require(std::isfinite(o.joint_escalation_step_rad) && o.joint_escalation_step_rad >= 0.0,
          "joint_escalation_step_rad must be finite and >= 0");
  require(o.rate_escalation_step >= 0.0 && o.rate_escalation_step < 1.0,
          "rate_escalation_step must be in [0, 1)");
  require(o.objective.panels_per_piece >= 1, "objective.panels_per_piece must be >= 1");
  require(o.objective.sample_chunks >= 1, "objective.sample_chunks must be >= 1");
  require(o.feasibility.sample_period_s > 0.0 && o.feasibility.rate_tolerance >= 0.0,
          "feasibility: sample_period_s must be > 0 and rate_tolerance >= 0");
  require(std::isfinite(o.objective.time_weight) && o.objective.time_weight >= 0.0,
          "objective.time_weight must be finite and >= 0");
  CheckLbfgsOptions(o.lbfgs);
  CheckWarmStartOptions(o.warm_start);
}

std::string_view ToString(TrajectoryOptimizerStatus status) {
  switch (status) {
    case TrajectoryOptimizerStatus::kSuccess: return "success";
    case TrajectoryOptimizerStatus::kNotConverged: return "not converged";
    case TrajectoryOptimizerStatus::kCancelled: return "cancelled";
    case TrajectoryOptimizerStatus::kInvalidInput: return "invalid input";
  }
  return "unknown";
}

ArcYawTrajectory TrajectoryOptimizerSummary::MakeTrajectory() const {
  if (num_pieces <= 0) {
    throw std::invalid_argument("TrajectoryOptimizerSummary::MakeTrajectory: no trajectory (" +
                                reason + ")");
  }
  if (parameterisation != TrajectoryParameterisation::kArcLengthYaw) {
    throw std::invalid_argument(
        "TrajectoryOptimizerSummary::MakeTrajectory: a flatness trajectory (use Sampled())");
  }
  ArcYawTrajectory::Options options;
  options.integrator.panels_per_piece = panels_per_piece;
  ArcYawTrajectory trajectory(static_cast<int>(head.rows()) - 2, num_pieces, options);
  trajectory.Update(p0_W, head, tail, waypoints, durations_s);
  return trajectory;
}

SampledTrajectory TrajectoryOptimizerSummary::Sampled() const {
  if (parameterisation == TrajectoryParameterisation::kFlatness) {
    if (num_pieces <= 0) {
      throw std::invalid_argument("TrajectoryOptimizerSummary::Sampled: no trajectory (" +
                                  reason + ")");
    }
    return SampleFlatness(flatness);
  }
  // SampleArcYaw holds the trajectory by reference: keep it alive with the samplers.
  const auto trajectory = std::make_shared<const ArcYawTrajectory>(MakeTrajectory());
  SampledTrajectory sampled = SampleArcYaw(*trajectory);
  sampled.make_sampler = [trajectory, make = std::move(sampled.make_sampler)]() {
    TrajectorySampler sampler = make();
    return TrajectorySampler([trajectory, sampler = std::move(sampler)](
                                 double t_s, TrajectorySample* sample) { sampler(t_s, sample); });
  };
  return sampled;
}

std::string TrajectoryOptimizerSummary::Report() const {
  std::ostringstream out;
  out << "TrajectoryOptimizer: " << ToString(status);
  if (!reason.empty()) out << " (" << reason << ")";
  out << "\n";
  if (num_pieces > 0) {
    out << Format("  trajectory: %.0f pieces, %.3f s; end effector error %.4f m / %.4f rad\n",
                  num_pieces, duration_s, ee_position_error_m, ee_orientation_error_rad);
  }
  out << Format("  iterations: stage 1 %.0f, stage 2 %.0f (%.0f outer, final rho %.3g",
                stage1_iterations, stage2_iterations, outer_iterations, final_rho)
      << Format(", %.0f penalty escalations)\n", penalty_escalations);
  out << Format("  objective evaluations %.0f; time %.2f ms", objective_evaluations,
                1e3 * total_s)
      << Format(" (warm start %.2f, stage 1 %.2f, stage 2 %.2f, check %.2f ms)\n",
                1e3 * warm_start_s, 1e3 * stage1_s, 1e3 * stage2_s, 1e3 * check_s);
  if (num_pieces > 0) {
    out << Format("  cost %.4g: jerk %.4g, time %.4g, end effector %.4g", final_cost.total,
                  final_cost.jerk, final_cost.time, final_cost.end_effector);
    for (int t = 0; t < kNumPenaltyTerms; ++t) {
      if (final_cost.penalties[t] > 0.0) {
        out << ", " << ToString(static_cast<PenaltyTerm>(t)) << " "
            << Format("%.3g", final_cost.penalties[t]);
      }
    }
    out << "\n";
    if (feasibility.num_samples > 0) {
      out << Format("  field check (%.0f samples): base %.4f m, arm %.4f m, self %.4f m,",
                    feasibility.num_samples, feasibility.min_base_clearance_m,
                    feasibility.min_arm_clearance_m, feasibility.min_self_clearance_m)
          << Format(" chassis %.4f m beyond requirement; worst rate ratio %.4f (",
                    feasibility.min_chassis_clearance_m, feasibility.max_rate_ratio)
          << feasibility.worst_rate << ")\n";
    }
  }
  return out.str();
}

struct TrajectoryOptimizer::Run {
  const TrajectoryProblem& problem;
  std::stop_token stop;
  Clock::time_point begin;
  Clock::time_point deadline;
  TrajectoryOptimizerSummary summary;
  WarmStart warm;
  std::unique_ptr<TrajectoryObjective> objective;
  Eigen::VectorXd x;
  bool cancelled = false;
  bool timed_out = false;
  bool checked = false;       ///< summary's trajectory and check are those of x.

  /// Records an inner solve's outcome; false if the run must stop (cancel, time limit).
  bool Account(const LbfgsResult& result, int* iterations) {
    *iterations += result.iterations;
    summary.objective_evaluations += result.evaluations;
    if (result.stop == LbfgsStop::kCancelled) cancelled = true;
    if (result.stop == LbfgsStop::kTimeLimit) timed_out = true;
    return !cancelled && !timed_out;
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
  // The penalty options (weights, margins, factors) are checked by building the penalties
  // once, with the model's own base limits.
  SamplePenalties check(kinematics, base_field, arm_field, kinematics.model().base_limits,
                        options_.objective.penalties);
  ReachHeights(kinematics, &min_reach_height_m_, &max_reach_height_m_);
}

std::string TrajectoryOptimizer::CheckProblem(const TrajectoryProblem& problem) const {
  const RobotModel& model = kinematics_.model();
  const WholeBodyState& start = problem.start;
  if (start.num_joints() != model.num_joints()) {
    return "start state has " + std::to_string(start.num_joints()) + " joints, the robot " +
           std::to_string(model.num_joints());
  }
  if (!start.IsFinite()) return "start state is not finite";
  for (int k = 0; k < model.num_joints(); ++k) {
    const double q = start.q_rad(k);
    if (q < model.joint_limits.q_min_rad(k) || q > model.joint_limits.q_max_rad(k)) {
      return "start joint " + std::to_string(k + 1) + " = " + std::to_string(q) +
             " rad is outside its limits";
    }
  }
  const BaseLimits& l = problem.base_limits;
  for (double limit : {l.v_max_mps, l.a_max_mps2, l.omega_max_radps, l.beta_max_radps2}) {
    if (!(std::isfinite(limit) && limit > 0.0)) return "base limits must be finite and > 0";
  }
  const Eigen::Isometry3d& goal = problem.X_WE_goal;
  if (!goal.matrix().allFinite()) return "goal pose X_WE_goal is not finite";
  if (!(goal.linear().transpose() * goal.linear()).isIdentity(1e-6)) {
    return "goal pose X_WE_goal's rotation is not orthonormal";
  }
  const double z = goal.translation().z();
  if (z < min_reach_height_m_ || z > max_reach_height_m_) {
    return "target out of reach: its height " + Format("%.3f m", z) +
           " is outside the arm's reach " +
           Format("[%.3f, %.3f] m", min_reach_height_m_, max_reach_height_m_);
  }
  // Clearly inside an obstacle: the 3D field, within one cell of the exact distance, is
  // negative by more than a cell.
  const double resolution = arm_field_.geometry().resolution_m;
  const double distance = arm_field_.Distance(goal.translation());
  if (distance < -resolution) {
    return "target inside an obstacle (3D field distance " + Format("%.3f m)", distance);
  }
  return "";
}

TrajectoryOptimizerSummary TrajectoryOptimizer::Optimize(const TrajectoryProblem& problem,
                                                         const WholeBodyPath& initial_path,
                                                         std::stop_token stop) const {
  Run run{problem, stop, Clock::now(), {}, {}, {}, nullptr, {}};
  run.deadline = run.begin + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(options_.time_limit_s));
  TrajectoryOptimizerSummary& summary = run.summary;
  summary.panels_per_piece = options_.objective.panels_per_piece;
  const auto fail = [&](TrajectoryOptimizerStatus status, const std::string& reason) {
    summary.status = status;
    summary.reason = reason;
    summary.total_s = SecondsSince(run.begin);
    return summary;
  };
  if (stop.stop_requested()) return fail(TrajectoryOptimizerStatus::kCancelled, "cancelled");
  const std::string problem_error = CheckProblem(problem);
  if (!problem_error.empty()) return fail(TrajectoryOptimizerStatus::kInvalidInput, problem_error);
  if (options_.parameterisation == TrajectoryParameterisation::kFlatness) {
    try {
      const FlatnessOptimizer flatness(kinematics_, base_field_, arm_field_,
                                       FlatnessOptionsFrom(options_));
      CopyFlatnessSummary(flatness.Optimize(problem, initial_path, stop), &summary);
    } catch (const std::invalid_argument& e) {  // options the baseline cannot take
      return fail(TrajectoryOptimizerStatus::kInvalidInput, std::string("flatness: ") + e.what());
    }
    summary.total_s = SecondsSince(run.begin);
    return summary;
  }
  try {
    run.warm = MakeWarmStart(initial_path, problem.start, problem.base_limits,
                             kinematics_.model().joint_limits, options_.objective.panels_per_piece,
                             options_.warm_start);
    run.objective = std::make_unique<TrajectoryObjective>(
        kinematics_, base_field_, arm_field_, problem.base_limits, problem.start,
        problem.X_WE_goal, run.warm.num_pieces, options_.objective);
    run.x = run.objective->Pack(run.warm.durations_s, run.warm.waypoints, run.warm.end);
  } catch (const std::invalid_argument& e) {
    return fail(TrajectoryOptimizerStatus::kInvalidInput, std::string("initial path: ") + e.what());
  }
  summary.warm_start_s = SecondsSince(run.begin);
  try {
    RunStages(&run);
    Finish(&run);
  } catch (const std::exception& e) {  // not expected: a bug, reported rather than thrown
    return fail(TrajectoryOptimizerStatus::kNotConverged,
                std::string("internal error: ") + e.what());
  }
  summary.total_s = SecondsSince(run.begin);
  return summary;
}

void TrajectoryOptimizer::RunStages(Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  TrajectoryOptimizerSummary& summary = run->summary;
  objective.set_stop_token(run->stop);
  if (options_.run_stage1 && options_.stage1_max_iterations > 0) {
    const Clock::time_point stage_start = Clock::now();
    objective.set_terms(Stage1Terms());
    objective.set_path_reference(run->warm.reference);
    LbfgsOptions lbfgs = options_.lbfgs;
    lbfgs.max_iterations = options_.stage1_max_iterations;
    const LbfgsResult result = SolveWithLbfgs(&objective, &run->x, lbfgs, run->deadline, run->stop);
    const bool go_on = run->Account(result, &summary.stage1_iterations);
    summary.stage1_s = SecondsSince(stage_start);
    if (!go_on) return;
  }
  // Stage 2: PHR-ALM on eq. (7) with every other term; while the result is infeasible on
  // the fields, the penalty weights are raised and the ALM continues from where it was.
  const Clock::time_point stage_start = Clock::now();
  objective.set_terms(ObjectiveTerms());
  Vector6d lambda = Vector6d::Zero();
  double rho = options_.alm_rho_initial;
  PenaltyValues scales = OnesPenaltyValues();
  PenaltyTightening tightening;
  for (int escalation = 0;; ++escalation) {
    if (!RunAugmentedLagrangian(run, &lambda, &rho)) break;
    if (CheckResult(run)) break;  // success
    if (summary.feasibility.feasible || escalation == options_.max_penalty_escalations) break;
    const FieldFeasibilityReport& report = summary.feasibility;
    EscalateViolatedPenalties(report, options_.feasibility, options_.penalty_escalation_factor,
                              &scales);
    objective.set_penalty_scales(scales);
    TightenViolatedThresholds(report, options_, &tightening);
    objective.set_tightening(tightening);
    ++summary.penalty_escalations;
  }
  summary.stage2_s = SecondsSince(stage_start);
}

bool TrajectoryOptimizer::RunAugmentedLagrangian(Run* run, Vector6d* lambda, double* rho) const {
  TrajectoryObjective& objective = *run->objective;
  TrajectoryOptimizerSummary& summary = run->summary;
  for (int outer = 0; outer < options_.alm_max_outer_iterations; ++outer) {
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
    if (r.head<3>().norm() <= options_.alm_position_tolerance_m &&
        r.tail<3>().norm() <= options_.alm_orientation_tolerance_rad) {
      return true;
    }
    // PHR-ALM update (eq. (7)): lambda <- lambda + rho r, rho <- min(growth rho, rho_max).
    *lambda += *rho * r;
    *rho = std::min(*rho * options_.alm_rho_growth, options_.alm_rho_max);
  }
  return true;
}

bool TrajectoryOptimizer::CheckResult(Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  TrajectoryOptimizerSummary& summary = run->summary;
  const Clock::time_point check_start = Clock::now();
  run->checked = false;
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
  summary.final_cost = objective.breakdown();
  const Vector6d& r = objective.end_effector_residual();
  summary.ee_position_error_m = r.head<3>().norm();
  summary.ee_orientation_error_rad = r.tail<3>().norm();
  summary.feasibility =
      CheckFeasibilityOnFields(objective.trajectory(), kinematics_, base_field_, arm_field_,
                               run->problem.base_limits, options_.feasibility);
  summary.check_s += SecondsSince(check_start);
  run->checked = true;
  return summary.feasibility.feasible &&
         summary.ee_position_error_m <= options_.ee_position_tolerance_m &&
         summary.ee_orientation_error_rad <= options_.ee_orientation_tolerance_rad;
}

void TrajectoryOptimizer::Finish(Run* run) const {
  TrajectoryObjective& objective = *run->objective;
  TrajectoryOptimizerSummary& summary = run->summary;
  objective.set_stop_token({});  // the final evaluation must run even after a cancel
  objective.set_terms(ObjectiveTerms());
  if (run->cancelled) {
    // The last iterate's trajectory, without the check: a cancel must return promptly.
    summary.status = TrajectoryOptimizerStatus::kCancelled;
    summary.reason = "cancelled";
    double cost = 0.0;
    ++summary.objective_evaluations;
    if (objective.Evaluate(run->x.data(), &cost, nullptr)) {
      summary.num_pieces = objective.num_pieces();
      summary.p0_W = objective.p0_W();
      summary.head = objective.head();
      summary.tail = objective.tail();
      summary.waypoints = objective.waypoints();
      summary.durations_s = objective.durations_s();
      summary.duration_s = objective.durations_s().sum();
    }
    return;
  }
  if (!run->checked) CheckResult(run);
  if (!run->checked) {
    summary.status = TrajectoryOptimizerStatus::kNotConverged;
    summary.reason = "the optimization diverged: the final objective is not finite";
    return;
  }
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
    summary.status = TrajectoryOptimizerStatus::kSuccess;
    summary.reason.clear();
    return;
  }
  if (run->timed_out) {
    problems.insert(problems.begin(), Format("time limit %.3f s reached", options_.time_limit_s));
  }
  summary.status = TrajectoryOptimizerStatus::kNotConverged;
  summary.reason.clear();
  for (const std::string& p : problems) {
    summary.reason += (summary.reason.empty() ? "" : "; ") + p;
  }
}

}  // namespace topay
