#pragma once
// The candidate base paths of a plan as a PLANNER_PATHS message (planner_paths_t): what the
// front end found, and which one the published trajectory follows (for viewers and logs).

#include <cstdint>

#include "core/planner/whole_body_plan_result.h"
#include "topay/planner_paths_t.hpp"

namespace topay::planner {

/// The base paths of `result`'s last round (front_end.base_paths, in order); `chosen` is the
/// index of the chosen candidate's base path (-1 if the plan has no chosen candidate).
planner_paths_t ToPathsMessage(const WholeBodyPlanResult& result, std::int64_t utime, std::int64_t goal_id,
                               std::int64_t trajectory_id);

}  // namespace topay::planner
