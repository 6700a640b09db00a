#pragma once
// What the fault-injection suite demands of every episode (issue 22): no ground-truth contact;
// no process other than the target dies; where the drives must stop, they are commanded to
// stop, within 100 ms of the last command where the command stream is what was lost; the
// mission resumes or reports a clear failure; every fault could be injected.

#include <string>
#include <vector>

#include "fault_catalog.h"
#include "fault_episode.h"

namespace topay::tools {

/// The longest time from the last CONTROL_COMMAND to the stop, ms (the 100 ms).
inline constexpr double kCommandLossStopLimitMs = 100.0;

/// Every violation, one readable line each ("kill-tracker seed 5: stopped 140 ms after the last
/// command (limit 100 ms)"); empty when the campaign passed.
std::vector<std::string> Violations(const std::vector<FaultSpec>& faults, const std::vector<EpisodeResult>& episodes);

}  // namespace topay::tools
