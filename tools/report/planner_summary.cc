#include "tools/report/planner_summary.h"

#include <algorithm>
#include <set>
#include <utility>

#include "procs/msgs/planner_status_text.h"

namespace topay::report {
namespace {

using PlanKey = std::pair<std::int64_t, std::int64_t>;  // (goal id, trajectory id)

// What the statuses have shown so far.
struct PlannerTally {
  std::map<std::int64_t, std::int32_t> replans_per_goal;
  std::map<std::int64_t, std::int64_t> goal_of_trajectory;  // the goal each trajectory id first came with
  std::set<PlanKey> succeeded, stopping;
  std::set<std::int64_t> failed, reached_at_rest;
  std::vector<double> planning_ms;
  std::map<std::string, std::int64_t> failure_reasons;
};

// A SUCCEEDED status is a plan when it names a trajectory of its own goal: the planner's
// status keeps the last trajectory id (and total_ms) after it, e.g. in "goal reached at rest"
// for the next goal, which is no plan.
bool IsPlan(const planner_status_t& s, PlannerTally* t) {
  if (s.trajectory_id == 0 || msgs::ReportsReachedAtRest(s)) return false;
  return t->goal_of_trajectory.emplace(s.trajectory_id, s.goal_id).first->second == s.goal_id;
}

void Add(const planner_status_t& s, PlannerTally* t) {
  if (s.goal_id != 0) {
    std::int32_t& replans = t->replans_per_goal[s.goal_id];
    replans = std::max(replans, s.replans);
  }
  const PlanKey plan{s.goal_id, s.trajectory_id};
  if (s.state == planner_status_t::SUCCEEDED) {
    if (msgs::ReportsReachedAtRest(s)) t->reached_at_rest.insert(s.goal_id);
    if (IsPlan(s, t) && t->succeeded.insert(plan).second) t->planning_ms.push_back(s.total_ms);
  } else if (s.state == planner_status_t::STOPPING) {
    t->stopping.insert(plan);
  } else if (s.state == planner_status_t::FAILED && t->failed.insert(s.goal_id).second) {
    ++t->failure_reasons[s.failure_reason];
  }
  if (s.trajectory_id != 0) t->goal_of_trajectory.emplace(s.trajectory_id, s.goal_id);
}

}  // namespace

PlannerSummary SummarizePlanner(const std::vector<planner_status_t>& statuses) {
  PlannerTally t;
  for (const planner_status_t& s : statuses) Add(s, &t);
  PlannerSummary summary;
  for (const auto& [goal, replans] : t.replans_per_goal) summary.replans += replans;
  summary.goals = static_cast<std::int64_t>(t.replans_per_goal.size());
  summary.stopping = static_cast<std::int64_t>(t.stopping.size());
  summary.reached_at_rest = static_cast<std::int64_t>(t.reached_at_rest.size());
  summary.planning_ms = SummarizeTimings(t.planning_ms);
  summary.failures = static_cast<std::int64_t>(t.failed.size());
  summary.failure_reasons = std::move(t.failure_reasons);
  return summary;
}

}  // namespace topay::report
