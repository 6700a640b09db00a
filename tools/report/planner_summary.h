#pragma once
// Replans, planning times and failures from PLANNER_STATUS (topay-planner), which is
// published on every change and periodically: repeated statuses of one plan count once.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "tools/report/sample_stats.h"
#include "topay/planner_status_t.hpp"

namespace topay::report {

struct PlannerSummary {
  /// Replans: the largest PLANNER_STATUS.replans seen per goal id, summed over the goals.
  std::int64_t replans = 0;
  std::int64_t goals = 0;  ///< distinct goal ids (non-zero) in PLANNER_STATUS
  /// STOPPING statuses, each (goal id, trajectory id) once: the stopping trajectories sent.
  std::int64_t stopping = 0;
  /// Goals the planner reported reached without a plan (SUCCEEDED "goal reached at rest": the
  /// end effector already at the target), each once.
  std::int64_t reached_at_rest = 0;
  /// total_ms of each SUCCEEDED plan, each (goal id, trajectory id) once (its repeats and its
  /// "trajectory N ended" status are the same plan). Not plans: SUCCEEDED statuses without a
  /// trajectory id, "goal reached at rest", and those naming a trajectory that came with
  /// another goal (the status keeps the last trajectory id and total_ms after a goal).
  TimingStats planning_ms;
  /// FAILED goals (each goal id once) and how many failed for each failure_reason.
  std::int64_t failures = 0;
  std::map<std::string, std::int64_t> failure_reasons;
};

PlannerSummary SummarizePlanner(const std::vector<planner_status_t>& statuses);

}  // namespace topay::report
