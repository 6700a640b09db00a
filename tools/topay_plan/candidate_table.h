#pragma once

#include <string>
#include <vector>

#include "core/planner/whole_body_plan_result.h"
#include "tools/topay_plan/plan_tool.h"

namespace topay::plan {

/// One row per back-end candidate of a plan, in candidate order: the base path it came from
/// (source, homotopy class, length), the optimizer's status, duration, iterations and wall
/// time, and the validator's verdict.
std::vector<CandidateRow> CandidateRows(const WholeBodyPlanResult& plan);

/// The rows as an aligned text table with a header line, each line indented by `indent`
/// and ending in a newline ("" for no rows).
std::string FormatCandidateTable(const std::vector<CandidateRow>& rows,
                                 const std::string& indent = "  ");

}  // namespace topay::plan
