#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/planning/front_end_result.h"

namespace topay::frontend_bench {

/// What the front-end benchmark counts over its tasks: outcomes, stage times (ms) and the
/// exact re-check of every returned path.
struct FrontEndTally {
  int tasks = 0;
  int tasks_ok = 0;        ///< a path, and every path passed the exact check
  int unreachable = 0;     ///< certified unsolvable (core/planning/base_reachability.h)
  int unreachable_ok = 0;  ///< ... yet given a path: must stay 0
  int paths = 0;
  int paths_failing_exact_check = 0;
  int jobs_finished = 0;  ///< ran to their own end (not cancelled by the window or budget)
  int jobs_succeeded = 0;
  int jobs_cancelled = 0;
  std::vector<double> topology_ms, classes, base_paths, rrt_first_ms, total_ms, goal_ms;
  std::vector<double> prm_ms, dfs_ms, shortcut_ms, pruning_ms, jps_ms, acquisition_ms;
  int fallback_searches = 0;
  int reachable_goal_searches = 0;
  std::map<std::string, int> statuses;
  std::vector<std::string> exact_failures;
};

/// One task's outcome, as the benchmark sees it.
struct FrontEndTaskOutcome {
  int index = 0;
  bool certified_unreachable = false;
  std::vector<std::string> exact_failures;  ///< messages of paths failing the exact check
};

/// Adds one task's front-end result and its checks to the tally.
void AddToTally(const FrontEndResult& result, const FrontEndTaskOutcome& outcome,
                FrontEndTally* tally);

}  // namespace topay::frontend_bench
