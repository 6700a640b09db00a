#pragma once
// The run summary as text for the terminal (topay-report's output, the demo's end).

#include <string>

#include "tools/report/run_summary.h"

namespace topay::report {

/// Several lines: the mission's result, time and steps; replans; collisions; tracking errors
/// and solve times; planning times and failures; distance and appeared boxes; messages and
/// decode failures per channel; the log and the files written.
std::string FormatSummary(const RunSummary& summary);

}  // namespace topay::report
