#include "core/planner/deterministic_options.h"

#include <algorithm>
#include <limits>

namespace topay {

void MakeDeterministic(WholeBodyPlannerOptions* options, const DeterministicBudgets& budgets) {
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  FrontEndOptions& front_end = options->front_end;
  front_end.num_threads = 1;
  front_end.ik.time_budget_s = kUnbounded;
  front_end.topology.prm.max_time_s = 0.0;  // <= 0: samples only
  front_end.topology.prm.max_samples = budgets.prm_samples;
  front_end.rrt.time_budget_s = kUnbounded;
  front_end.rrt.max_iterations = budgets.rrt_iterations;
  front_end.improvement_window_s = kUnbounded;
  front_end.acquisition_budget_s = kUnbounded;
  options->num_threads = 1;
  options->early_termination_window_s = 0.0;
  // One candidate's optimization is bounded by its iteration caps (L-BFGS, ALM outer loops,
  // escalations), not by its own wall-clock limit, which a loaded machine would reach at a
  // different iteration; only the plan's time limit still bounds the whole (and must be
  // finite for the flatness baseline's check, hence the cap).
  constexpr double kLongestOptimizationS = 1e6;
  options->optimizer.time_limit_s = std::min(options->time_limit_s, kLongestOptimizationS);
  // Retry rounds (PlanRetryOptions) are not cut by a share of the wall-clock time left, and
  // start whatever time is left: a round ends at the same iteration on every machine.
  options->retry.round_time_share = 1.0;
  options->retry.min_time_left_s = 0.0;
}

}  // namespace topay
