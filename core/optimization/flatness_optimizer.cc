#include "core/optimization/flatness_optimizer.h"

#include "core/optimization/lbfgs_solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>


namespace topay {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0,
                   double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c, d);
  return buffer;
}

/// One L-BFGS solve from *x (lbfgs_solve.h, shared with the arc length-yaw driver); returns
/// the iterations; *aborted on stop or deadline.
int Solve(FlatnessObjective* objective, Eigen::VectorXd* x, const LbfgsOptions& lbfgs,
          Clock::time_point deadline, std::stop_token stop, bool* aborted) {
  const LbfgsResult result = SolveWithLbfgs(objective, x, lbfgs, deadline, std::move(stop));
  *aborted = result.stop == LbfgsStop::kCancelled || result.stop == LbfgsStop::kTimeLimit ||
             objective->stopped();
  return result.iterations;
}

}  // namespace

SampledTrajectory FlatnessOptimizerSummary::Sampled() const {
  if (num_pieces == 0) {
    throw std::invalid_argument("FlatnessOptimizerSummary::Sampled: no trajectory (" +
                                reason + ")");
  }
  return SampleFlatness(trajectory);
}

std::string FlatnessOptimizerSummary::Report() const {
  std::ostringstream out;
  out << "Flatness baseline: " << ToString(status);
  if (!reason.empty()) out << " (" << reason << ")";
  out << "\n";
  if (num_pieces > 0) {
    out << Format("  trajectory: %.0f pieces, %.3f s; end effector error %.4f m / %.4f rad\n",
                  num_pieces, duration_s, ee_position_error_m, ee_orientation_error_rad);
    out << Format("  cost %.4g: jerk %.4g, time %.4g, min speed %.3g\n", final_cost.total,
                  final_cost.jerk, final_cost.time, final_cost.min_speed);
  }
  out << Format("  %.0f outer, %.0f L-BFGS iterations, %.0f evaluations, %.2f ms\n",
                outer_iterations, iterations, objective_evaluations, 1e3 * total_s);
  return out.str();
}

FlatnessOptimizer::FlatnessOptimizer(const Kinematics& kinematics,
                                     const SignedDistanceField2& base_field,
                                     const SignedDistanceField3& arm_field,
                                     FlatnessOptimizerOptions options)
    : kinematics_(kinematics),
      base_field_(base_field),
      arm_field_(arm_field),
      options_(std::move(options)) {
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("FlatnessOptimizerOptions: ") + what);
  };
  const FlatnessOptimizerOptions& o = options_;
  CheckLbfgsOptions(o.lbfgs);
  require(std::isfinite(o.alm_rho_initial) && o.alm_rho_initial > 0.0,
          "alm_rho_initial must be finite and > 0");
  require(o.alm_rho_growth >= 1.0, "alm_rho_growth must be >= 1");
  require(o.alm_rho_max >= o.alm_rho_initial, "alm_rho_max must be >= alm_rho_initial");
  require(o.alm_max_outer_iterations >= 1, "alm_max_outer_iterations must be >= 1");
  require(o.alm_position_tolerance_m > 0.0 && o.alm_orientation_tolerance_rad > 0.0 &&
              o.ee_position_tolerance_m > 0.0 && o.ee_orientation_tolerance_rad > 0.0,
          "tolerances must be > 0");
  require(std::isfinite(o.check_period_s) && o.check_period_s > 0.0,
          "check_period_s must be finite and > 0");
  require(std::isfinite(o.time_limit_s) && o.time_limit_s > 0.0,
          "time_limit_s must be finite and > 0");
  SamplePenalties check(kinematics, base_field, arm_field, kinematics.model().base_limits,
                        o.objective.penalties);  // throws for bad penalty options
}

std::string FlatnessOptimizer::CheckProblem(const TrajectoryProblem& problem) const {
  const RobotModel& model = kinematics_.model();
  const WholeBodyState& start = problem.start;
  if (start.num_joints() != model.num_joints()) {
    return "start state has " + std::to_string(start.num_joints()) + " joints, the robot " +
           std::to_string(model.num_joints());
  }
  if (!start.IsFinite()) return "start state is not finite";
  const BaseLimits& l = problem.base_limits;
  for (double limit : {l.v_max_mps, l.a_max_mps2, l.omega_max_radps, l.beta_max_radps2}) {
    if (!(std::isfinite(limit) && limit > 0.0)) return "base limits must be finite and > 0";
  }
  if (!problem.X_WE_goal.matrix().allFinite()) return "goal pose X_WE_goal is not finite";
  return "";
}

FlatnessOptimizerSummary FlatnessOptimizer::Optimize(const TrajectoryProblem& problem,
                                                     const WholeBodyPath& initial_path,
                                                     std::stop_token stop) const {
  const Clock::time_point begin = Clock::now();
  const Clock::time_point deadline =
      begin + std::chrono::duration_cast<Clock::duration>(
                  std::chrono::duration<double>(options_.time_limit_s));
  FlatnessOptimizerSummary summary;
  const auto finish = [&](TrajectoryOptimizerStatus status, const std::string& reason) {
    summary.status = status;
    summary.reason = reason;
    summary.total_s = SecondsSince(begin);
    return summary;
  };
  if (stop.stop_requested()) return finish(TrajectoryOptimizerStatus::kCancelled, "cancelled");
  const std::string error = CheckProblem(problem);
  if (!error.empty()) return finish(TrajectoryOptimizerStatus::kInvalidInput, error);
  std::unique_ptr<FlatnessObjective> objective;
  Eigen::VectorXd x;
  try {
    const int K = options_.objective.panels_per_piece;
    const WarmStart warm =
        MakeWarmStart(initial_path, problem.start, problem.base_limits,
                      kinematics_.model().joint_limits, K, options_.warm_start);
    const int M = warm.num_pieces, N = kinematics_.num_joints();
    objective = std::make_unique<FlatnessObjective>(kinematics_, base_field_, arm_field_,
                                                    problem.base_limits, problem.start,
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
    x = objective->Pack(warm.durations_s, waypoints, end);
  } catch (const std::invalid_argument& e) {
    return finish(TrajectoryOptimizerStatus::kInvalidInput,
                  std::string("initial path: ") + e.what());
  }
  try {
    objective->set_stop_token(stop);
    Vector6d lambda = Vector6d::Zero();
    double rho = options_.alm_rho_initial;
    bool aborted = false;
    double cost = 0.0;
    for (int outer = 0; outer < options_.alm_max_outer_iterations && !aborted; ++outer) {
      objective->set_multiplier(lambda, rho);
      summary.iterations += Solve(objective.get(), &x, options_.lbfgs, deadline, stop, &aborted);
      ++summary.outer_iterations;
      if (aborted || !objective->Evaluate(x.data(), &cost, nullptr)) break;
      const Vector6d r = objective->end_effector_residual();
      if (r.head<3>().norm() <= options_.alm_position_tolerance_m &&
          r.tail<3>().norm() <= options_.alm_orientation_tolerance_rad) {
        break;
      }
      lambda += rho * r;  // PHR-ALM update, eq. (7)
      rho = std::min(rho * options_.alm_rho_growth, options_.alm_rho_max);
    }
    summary.objective_evaluations = objective->num_evaluations();
    if (stop.stop_requested()) return finish(TrajectoryOptimizerStatus::kCancelled, "cancelled");
    objective->set_stop_token({});
    if (!objective->Evaluate(x.data(), &cost, nullptr)) {
      return finish(TrajectoryOptimizerStatus::kNotConverged,
                    "the optimization diverged: the final objective is not finite (a zero "
                    "speed inside the trajectory?)");
    }
    summary.trajectory = objective->TrajectoryData();
    summary.num_pieces = summary.trajectory.num_pieces();
    summary.duration_s = summary.trajectory.duration_s();
    summary.final_cost = objective->breakdown();
    summary.ee_position_error_m = objective->end_effector_residual().head<3>().norm();
    summary.ee_orientation_error_rad = objective->end_effector_residual().tail<3>().norm();
    Check(problem, &summary);
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
    if (aborted && !problems.empty()) {
      problems = Format("time limit %.3f s reached; ", options_.time_limit_s) + problems;
    }
    return finish(problems.empty() ? TrajectoryOptimizerStatus::kSuccess
                                   : TrajectoryOptimizerStatus::kNotConverged,
                  problems);
  } catch (const std::exception& e) {
    return finish(TrajectoryOptimizerStatus::kNotConverged,
                  std::string("internal error: ") + e.what());
  }
}

// Every check_period_s (and at the end): the sample penalties at the full rate limits with no
// joint margin; each term's worst value is recorded (> 0: violated).
void FlatnessOptimizer::Check(const TrajectoryProblem& problem,
                              FlatnessOptimizerSummary* summary) const {
  SamplePenaltyOptions options = options_.objective.penalties;
  options.rate_limit_fraction = 1.0;
  options.joint_position_margin_rad = 0.0;
  SamplePenalties penalties(kinematics_, base_field_, arm_field_, problem.base_limits, options);
  FlatnessTrajectory trajectory(summary->trajectory);
  TrajectorySample sample;
  sample.state.q_rad.setZero(trajectory.num_joints());
  sample.qd_radps.setZero(trajectory.num_joints());
  sample.qdd_radps2.setZero(trajectory.num_joints());
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
