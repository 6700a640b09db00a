#pragma once

#include "core/planner/whole_body_planner_options.h"

namespace topay {

/// Work budgets of a deterministic plan (MakeDeterministic). The defaults keep a plan's work
/// close to what the wall-clock budgets allow on the 2-core benchmark machine.
struct DeterministicBudgets {
  /// Visibility PRM samples (instead of the 10 ms budget; front_end_test uses 2000 too).
  int prm_samples = 2000;
  /// Iterations of each anytime arm RRT* job (instead of t_smax = 0.2 s).
  std::int64_t rrt_iterations = 600;
};

/// Turns `options` into a plan that depends only on its inputs and seeds, not on the machine's
/// speed or load (the benchmark's `--threads 1`: same seed, same tasks.jsonl):
///  - one worker in the front end and one in the back end;
///  - wall-clock budgets replaced by work budgets: the IK by its restarts, the PRM by
///    budgets.prm_samples, each arm RRT* job by budgets.rrt_iterations (anytime, as before);
///  - every arm job runs to its end (no improvement window, no acquisition budget), one
///    after another, in path order;
///  - the back end stops at the first validated trajectory (an early-termination window of 0:
///    with one worker, no other candidate has started by then).
///  - each candidate's optimization is bounded by its iteration caps: its own wall-clock
///    limit is raised to the plan's (a loaded machine would reach it at another iteration);
///  - retry rounds (PlanRetryOptions) are not cut by a share of the time left and start
///    whatever time is left.
/// The outer bound stays, as safety: the plan's time_limit_s. A plan that reaches it is a
/// failure that may not repeat exactly.
void MakeDeterministic(WholeBodyPlannerOptions* options, const DeterministicBudgets& budgets = {});

}  // namespace topay
