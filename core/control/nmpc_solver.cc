#include "core/control/nmpc_solver.h"

#include <algorithm>

#include "core/common/stopwatch.h"
#include "core/control/command_projection.h"
#include "core/control/warm_start_shift.h"

namespace topay {
namespace {

ceres::Solver::Options MakeSolverOptions(const NmpcOptions& options) {
  ceres::Solver::Options solver;
  solver.minimizer_type = ceres::TRUST_REGION;
  solver.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  solver.num_threads = 1;
  solver.max_num_iterations = options.max_iterations;
  solver.function_tolerance = 1e-5;
  solver.gradient_tolerance = 1e-10;
  solver.parameter_tolerance = 1e-6;
  solver.logging_type = ceres::SILENT;
  solver.minimizer_progress_to_stdout = false;
  return solver;
}

ceres::Problem::Options ProblemOptions() {
  ceres::Problem::Options options;
  options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  // Parameters are set once and never removed; skip Ceres's per-solve checks where it can.
  options.enable_fast_removal = false;
  return options;
}

}  // namespace

NmpcSolver::NmpcSolver(const NmpcOptions& options, const TrackerLimits& limits)
    : options_(options), limits_(limits), num_joints_(limits.num_joints()) {
  options_.Check();
  limits_.Check();
  const int N = options_.horizon_steps;
  solution_ = InputSequence::Zero(N, num_joints_);
  warm_start_ = InputSequence::Zero(N, num_joints_);
  base_inputs_.setZero(2, N);
  joint_inputs_.setZero(N, num_joints_);
  solver_options_ = MakeSolverOptions(options_);

  // The base problem: one block of 2N inputs, speed limits as exact bounds.
  base_problem_ = std::make_unique<ceres::Problem>(ProblemOptions());
  base_cost_ = new BaseTrackingCost(options_, limits_);
  base_problem_->AddResidualBlock(base_cost_, nullptr, base_inputs_.data());
  for (int k = 0; k < N; ++k) {
    base_problem_->SetParameterLowerBound(base_inputs_.data(), 2 * k, -limits_.base.v_max_mps);
    base_problem_->SetParameterUpperBound(base_inputs_.data(), 2 * k, limits_.base.v_max_mps);
    base_problem_->SetParameterLowerBound(base_inputs_.data(), 2 * k + 1,
                                          -limits_.base.omega_max_radps);
    base_problem_->SetParameterUpperBound(base_inputs_.data(), 2 * k + 1,
                                          limits_.base.omega_max_radps);
  }
  // One problem per joint: N velocities, the velocity limit as exact bounds.
  for (int j = 0; j < num_joints_; ++j) {
    auto problem = std::make_unique<ceres::Problem>(ProblemOptions());
    auto* cost = new JointTrackingCost(options_, j, limits_.qdd_max_radps2(j));
    double* block = joint_inputs_.col(j).data();
    problem->AddResidualBlock(cost, nullptr, block);
    for (int k = 0; k < N; ++k) {
      problem->SetParameterLowerBound(block, k, -limits_.qd_max_radps(j));
      problem->SetParameterUpperBound(block, k, limits_.qd_max_radps(j));
    }
    joint_costs_.push_back(cost);
    joint_problems_.push_back(std::move(problem));
  }
}

NmpcSolver::~NmpcSolver() = default;

void NmpcSolver::set_time_budget_s(double budget_s) {
  NmpcOptions changed = options_;
  changed.time_budget_s = budget_s;
  changed.Check();
  options_ = changed;
}

void NmpcSolver::ResetWarmStart() {
  has_solution_ = false;
  ++summary_.num_warm_resets;
}

void NmpcSolver::PrepareWarmStart(const ControlCommand& last_command) {
  if (has_solution_) {
    ShiftInputSequence(solution_, options_.control_period_s / options_.step_s, &warm_start_);
  } else {
    warm_start_.Fill(last_command);
  }
  // The fallback is this warm start made feasible (it also starts Ceres inside its bounds).
  ProjectInputSequence(last_command, options_.control_period_s, options_.step_s, limits_,
                       &warm_start_);
}

bool NmpcSolver::SolveProblem(ceres::Problem* problem, double remaining_s, int* iterations,
                              double* initial_cost, double* final_cost) {
  if (remaining_s <= 0.0) return true;  // out of time: the caller falls back
  solver_options_.max_solver_time_in_seconds = remaining_s;
  ceres::Solve(solver_options_, problem, &ceres_summary_);
  *iterations += static_cast<int>(ceres_summary_.iterations.size());
  if (initial_cost != nullptr) *initial_cost = ceres_summary_.initial_cost;
  if (final_cost != nullptr) *final_cost = ceres_summary_.final_cost;
  return ceres_summary_.IsSolutionUsable();
}

const InputSequence& NmpcSolver::Solve(const WholeBodyState& state,
                                       const ReferenceHorizon& reference,
                                       const ControlCommand& last_command) {
  const Stopwatch watch;
  const double budget_s = options_.time_budget_s;
  summary_.base_iterations = 0;
  summary_.joint_iterations = 0;
  summary_.base_initial_cost = summary_.base_final_cost = 0.0;
  summary_.base_solve_ms = summary_.joint_solve_ms = 0.0;
  PrepareWarmStart(last_command);

  // The base problem from the warm start.
  bool usable = true;
  base_inputs_ = warm_start_.u_base;
  base_cost_->SetProblem(Eigen::Vector3d(state.x_m, state.y_m, state.yaw_rad), &reference,
                         Eigen::Vector2d(last_command.v_mps, last_command.omega_radps));
  const double base_start_ms = watch.ElapsedMs();
  usable = SolveProblem(base_problem_.get(), budget_s - watch.ElapsedS(),
                        &summary_.base_iterations, &summary_.base_initial_cost,
                        &summary_.base_final_cost);
  summary_.base_solve_ms = watch.ElapsedMs() - base_start_ms;

  // The joint problems, each from its warm start, with what remains of the budget.
  const double joints_start_ms = watch.ElapsedMs();
  for (int j = 0; j < num_joints_ && usable && watch.ElapsedS() < budget_s; ++j) {
    joint_inputs_.col(j) = warm_start_.qd_radps.row(j).transpose();
    joint_costs_[j]->SetProblem(state.q_rad(j), &reference, last_command.qd_radps(j));
    usable = SolveProblem(joint_problems_[j].get(), budget_s - watch.ElapsedS(),
                          &summary_.joint_iterations, nullptr, nullptr);
  }
  summary_.joint_solve_ms = watch.ElapsedMs() - joints_start_ms;

  const bool over_budget = watch.ElapsedS() >= budget_s;
  summary_.fell_back = over_budget || !usable;
  summary_.num_over_budget += over_budget;
  summary_.num_failed += !usable && !over_budget;
  if (summary_.fell_back) {
    solution_ = warm_start_;  // the shifted previous solution (already feasible)
  } else {
    solution_.u_base = base_inputs_;
    solution_.qd_radps = joint_inputs_.transpose();
  }
  // Every returned input within every limit, chained from the last command.
  summary_.projected_inputs = ProjectInputSequence(last_command, options_.control_period_s,
                                                   options_.step_s, limits_, &solution_);
  has_solution_ = true;
  ++summary_.num_solves;
  summary_.solve_ms = watch.ElapsedMs();
  return solution_;
}

}  // namespace topay
