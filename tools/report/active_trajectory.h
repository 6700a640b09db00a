#pragma once
// Which logged trajectory the robot was following at a time, as the tracker switches: a
// trajectory becomes active at its start_utime, or when it was published if that is later
// (the tracker cannot follow it before it has it), and stays active until a newer one (later
// in the log) becomes active.

#include <cstdint>
#include <optional>
#include <vector>

#include "tools/report/run_log.h"

namespace topay::report {

/// max(start_utime, publication utime) of a logged trajectory, us.
std::int64_t ActivationUtime(const LoggedTrajectory& trajectory);

/// The index into `trajectories` (log order) of the newest one whose activation is at or
/// before utime; nullopt if none is active yet.
std::optional<std::size_t> ActiveTrajectoryAt(const std::vector<LoggedTrajectory>& trajectories,
                                              std::int64_t utime);

/// The activation utimes of the trajectories that do become active (those superseded by a
/// newer one before their activation never do), increasing.
std::vector<std::int64_t> TrajectorySwitchUtimes(const std::vector<LoggedTrajectory>& trajectories);

}  // namespace topay::report
