#include "tools/report/mission_summary.h"

#include <algorithm>

namespace topay::report {
namespace {

MissionResult ResultOf(std::int8_t state) {
  switch (state) {
    case mission_status_t::SUCCEEDED: return MissionResult::kSucceeded;
    case mission_status_t::FAILED: return MissionResult::kFailed;
    case mission_status_t::ABORTED: return MissionResult::kAborted;
    default: return MissionResult::kNone;
  }
}

// Ends the last step at `status` (its time runs until then).
void EndLastStep(const mission_status_t& status, std::vector<MissionStepSummary>* steps) {
  if (steps->empty()) return;
  MissionStepSummary& last = steps->back();
  last.time_s = status.elapsed_s - last.start_s;
  last.end_utime = status.utime;
}

}  // namespace

std::string ToString(MissionResult result) {
  switch (result) {
    case MissionResult::kSucceeded: return "SUCCEEDED";
    case MissionResult::kFailed: return "FAILED";
    case MissionResult::kAborted: return "ABORTED";
    case MissionResult::kNone: break;
  }
  return "none";
}

MissionSummary SummarizeMission(const std::vector<mission_status_t>& statuses) {
  MissionSummary summary;
  for (const mission_status_t& status : statuses) {
    if (status.state == mission_status_t::IDLE) continue;
    std::vector<MissionStepSummary>& steps = summary.steps;
    if (steps.empty() || status.step_index != steps.back().index) {
      EndLastStep(status, &steps);
      const bool moving = status.step.starts_with("goto") || status.step.starts_with("home");
      steps.push_back({status.step_index, status.step, status.elapsed_s, 0.0, moving, 0, status.utime});
    }
    if (steps.back().moving) steps.back().attempts = std::max(steps.back().attempts, static_cast<int>(status.attempts));
    EndLastStep(status, &steps);
  }
  if (statuses.empty()) return summary;
  const mission_status_t& last = statuses.back();
  summary.name = last.mission;
  summary.result = ResultOf(last.state);
  summary.detail = last.detail;
  summary.elapsed_s = last.elapsed_s;
  summary.num_steps = last.num_steps;
  return summary;
}

}  // namespace topay::report
