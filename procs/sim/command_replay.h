#pragma once
// Lockstep replay of a recorded command stream: the commands of an LCM log (CONTROL_COMMAND)
// go into a SimCore at the plant step of their own time, with no clock involved. Same scene,
// seeds and log: the same states and scans (output_digest.h).

#include <cstdint>
#include <string>
#include <vector>

#include "procs/sim/sim_core.h"
#include "topay/control_command_t.hpp"

namespace topay::simproc {

struct TimedCommand {
  std::int64_t utime = 0;  ///< the command's own utime
  control_command_t command;
};

/// The `channel` messages of the LCM log at `path` that decode as control_command_t, in log
/// order (others are counted in *skipped if given). Throws ConfigError(path, ...) if the log
/// cannot be opened.
std::vector<TimedCommand> ReadCommandLog(const std::string& path, const std::string& channel,
                                         std::int64_t* skipped = nullptr);

/// Runs `core` from its current step to end_s (sim seconds), giving each command at the first
/// step at or after (utime - epoch_utime) (commands before the core's time go in at once).
/// Returns the number of commands the plant rejected. With step_us, the wall time of every
/// core step (microseconds; steady clock) is appended.
std::int64_t ReplayCommands(SimCore* core, const std::vector<TimedCommand>& commands,
                            std::int64_t epoch_utime, double end_s, std::vector<double>* step_us = nullptr);

}  // namespace topay::simproc

namespace topay::simproc {

/// "core step (no scan): median 2.1 us, p95 3.0 us over 4900 steps; with a LiDAR scan: ..."
/// from the step times of ReplayCommands (steps k with k % steps_per_scan == 0 scanned;
/// steps_per_scan 0: none did).
std::string StepTimeSummary(const std::vector<double>& step_us, std::int64_t steps_per_scan);

}  // namespace topay::simproc
