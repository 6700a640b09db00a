#pragma once
// The mission's outcome and per-step times from MISSION_STATUS (topay-mission).

#include <cstdint>
#include <string>
#include <vector>

#include "topay/mission_status_t.hpp"

namespace topay::report {

/// How the mission ended: the state of the last MISSION_STATUS if it is a final one
/// (SUCCEEDED, FAILED, ABORTED); kNone without MISSION_STATUS or when the log ends while the
/// mission is IDLE or RUNNING.
enum class MissionResult { kNone, kSucceeded, kFailed, kAborted };

/// "SUCCEEDED", "FAILED", "ABORTED" or "none".
std::string ToString(MissionResult result);

/// One step as MISSION_STATUS's step_index transitions show it.
struct MissionStepSummary {
  int index = 0;              ///< 0-based step_index
  std::string description;    ///< e.g. "goto pickup"
  double start_s = 0.0;       ///< elapsed_s of the first status of this step
  double time_s = 0.0;        ///< until the first status of a later step (or the last status)
  bool moving = false;        ///< a goto or home step (its description starts with "goto" or "home")
  /// Moving steps: the largest `attempts` reported for the step (plans sent). 0 for the
  /// others (MISSION_STATUS.attempts keeps the last goto's count during them).
  int attempts = 0;
  std::int64_t end_utime = 0; ///< utime of the status that ended it (the next step's first, or the last)
};

struct MissionSummary {
  std::string name;           ///< the mission's name ("" without MISSION_STATUS)
  MissionResult result = MissionResult::kNone;
  std::string detail;         ///< the last status's detail (the failure's reason)
  double elapsed_s = 0.0;     ///< the last status's elapsed_s
  int num_steps = 0;
  std::vector<MissionStepSummary> steps;  ///< the steps seen, in order
};

/// Steps are taken from the RUNNING and final statuses (IDLE ones are before the start).
MissionSummary SummarizeMission(const std::vector<mission_status_t>& statuses);

}  // namespace topay::report
