#include "tools/report/planner_summary.h"

#include <algorithm>
#include <set>
#include <utility>

namespace topay::report {

PlannerSummary SummarizePlanner(const std::vector<planner_status_t>& statuses) {
  PlannerSummary summary;
  std::map<std::int64_t, std::int32_t> replans_per_goal;
  std::set<std::pair<std::int64_t, std::int64_t>> succeeded, stopping;
  std::set<std::int64_t> failed;
  std::vector<double> planning_ms;
  for (const planner_status_t& s : statuses) {
    if (s.goal_id != 0) {
      std::int32_t& replans = replans_per_goal[s.goal_id];
      replans = std::max(replans, s.replans);
    }
    const std::pair<std::int64_t, std::int64_t> plan{s.goal_id, s.trajectory_id};
    if (s.state == planner_status_t::SUCCEEDED && succeeded.insert(plan).second) {
      planning_ms.push_back(s.total_ms);
    } else if (s.state == planner_status_t::STOPPING) {
      stopping.insert(plan);
    } else if (s.state == planner_status_t::FAILED && failed.insert(s.goal_id).second) {
      ++summary.failure_reasons[s.failure_reason];
    }
  }
  for (const auto& [goal, replans] : replans_per_goal) summary.replans += replans;
  summary.goals = static_cast<std::int64_t>(replans_per_goal.size());
  summary.stopping = static_cast<std::int64_t>(stopping.size());
  summary.planning_ms = SummarizeTimings(planning_ms);
  summary.failures = static_cast<std::int64_t>(failed.size());
  return summary;
}

}  // namespace topay::report
