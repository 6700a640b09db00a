#pragma once

#include <optional>

#include "core/planner/whole_body_planner_options.h"
#include "core/robot/robot_model.h"
#include "tools/topay_plan/base_limit_choice.h"

namespace topay::plan {

/// Planner settings a tool's flags override. Precedence: the options structs' defaults, then
/// the planner YAML, then a flag that was given; an unset field leaves what the YAML (or
/// the default) says.
struct PlannerOverrides {
  std::optional<int> num_threads;        ///< planner.num_threads and front_end.num_threads
  std::optional<double> time_limit_s;    ///< planner.time_limit_s (bounds the whole plan)
  std::optional<bool> sequential;        ///< planner.sequential (the "Sequential" ablation)
  std::optional<BaseLimitChoice> base_limits;  ///< see BaseLimitChoiceInForce
  std::optional<double> optimizer_time_limit_s;  ///< optimizer.time_limit_s
  std::optional<double> acquisition_budget_s;    ///< front_end.acquisition_budget_s
};

/// Applies the given overrides to `options` (loaded from the YAML) and sets the base limits
/// in force (BaseLimitChoiceInForce of the flag and the YAML's planner.base_limits). Returns
/// the base limit choice in force. Throws tools::UsageError for kConfig when the YAML sets no
/// planner.base_limits.
BaseLimitChoice ApplyPlannerOverrides(const PlannerOverrides& overrides, const RobotModel& model,
                                      WholeBodyPlannerOptions* options);

}  // namespace topay::plan
