#include "tools/topay_frontend_bench/front_end_tally.h"

namespace topay::frontend_bench {
namespace {

void AddStageTimes(const FrontEndResult& result, FrontEndTally* tally) {
  if (result.stats.num_goal_attempts == 0) return;
  tally->topology_ms.push_back(result.stats.topology_ms);
  tally->classes.push_back(result.stats.num_classes_kept);
  tally->base_paths.push_back(result.stats.num_base_paths);
  tally->prm_ms.push_back(result.topology.prm_ms);
  tally->dfs_ms.push_back(result.topology.dfs_ms);
  tally->shortcut_ms.push_back(result.topology.shortcut_ms);
  tally->pruning_ms.push_back(result.topology.pruning_ms);
  tally->jps_ms.push_back(result.topology.jps_ms);
  tally->acquisition_ms.push_back(result.stats.acquisition_ms);
  tally->fallback_searches += result.stats.used_fallback_base_clearance ? 1 : 0;
  tally->reachable_goal_searches += result.stats.used_reachable_goal_search ? 1 : 0;
}

void AddJobs(const FrontEndResult& result, FrontEndTally* tally) {
  for (const ArmJobReport& job : result.jobs) {
    if (job.status == ArmRrtStarStatus::kCancelled || job.stats.cancelled || !job.started) {
      ++tally->jobs_cancelled;
    }
    if (job.status == ArmRrtStarStatus::kSuccess) {
      ++tally->jobs_succeeded;
      tally->rrt_first_ms.push_back(1e3 * job.stats.time_to_first_solution_s);
    }
    if (job.status != ArmRrtStarStatus::kCancelled && job.started) ++tally->jobs_finished;
  }
}

}  // namespace

void AddToTally(const FrontEndResult& result, const FrontEndTaskOutcome& outcome,
                FrontEndTally* tally) {
  ++tally->tasks;
  ++tally->statuses[std::string(ToString(result.status))];
  tally->total_ms.push_back(result.stats.total_ms);
  tally->goal_ms.push_back(result.stats.goal_ms);
  AddStageTimes(result, tally);
  AddJobs(result, tally);
  tally->paths += static_cast<int>(result.paths.size());
  tally->paths_failing_exact_check += static_cast<int>(outcome.exact_failures.size());
  for (const std::string& message : outcome.exact_failures) {
    tally->exact_failures.push_back("task " + std::to_string(outcome.index) + ": " + message);
  }
  if (result.success() && outcome.exact_failures.empty()) ++tally->tasks_ok;
  tally->unreachable += outcome.certified_unreachable ? 1 : 0;
  tally->unreachable_ok += outcome.certified_unreachable && result.success() ? 1 : 0;
}

}  // namespace topay::frontend_bench
