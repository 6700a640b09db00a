#pragma once
// The run summary as JSON (topay-report's summary.json; keys in docs/report.md).

#include <string>

#include <nlohmann/json.hpp>

#include "tools/report/run_summary.h"

namespace topay::report {

/// Every field of the summary: {"log", "mission", "planner", "collisions", "tracking",
/// "distance_driven_m", "appeared_boxes", "channels", "decode_failures", "files"}.
nlohmann::json SummaryToJson(const RunSummary& summary);

/// Writes SummaryToJson (indented) to path; throws std::runtime_error "<path>: cannot write".
void WriteSummaryJson(const RunSummary& summary, const std::string& path);

}  // namespace topay::report
