#include "core/planning/front_end_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

void CheckFrontEndOptions(const FrontEndOptions& o) {
  auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) {
      throw std::invalid_argument(std::string("FrontEndOptions::") + field + " must be " + rule);
    }
  };
  require(o.max_goal_attempts >= 1, "max_goal_attempts", ">= 1");
  require(o.improvement_window_s >= 0.0, "improvement_window_s", ">= 0 (+infinity: no limit)");
  require(o.acquisition_budget_s > 0.0, "acquisition_budget_s", "> 0 (+infinity: no limit)");
  require(std::isfinite(o.fallback_base_clearance_m) && o.fallback_base_clearance_m >= 0.0,
          "fallback_base_clearance_m", "finite and >= 0");
  require(o.other_way_turn_min_rad >= 0.0, "other_way_turn_min_rad", ">= 0 (+infinity: never)");
  require(o.num_threads >= 0, "num_threads", ">= 0 (0: all cores)");
  CheckGoalCandidatesOptions(o.goal);
  require(o.goal_retry.max_base_candidates >= 0, "goal_retry.max_base_candidates", ">= 0");
  require(o.goal_retry.restarts_per_base >= 1, "goal_retry.restarts_per_base", ">= 1");
  require(o.goal_retry.time_budget_s > 0.0, "goal_retry.time_budget_s", "> 0");
  require(o.goal_retry.max_total_iterations >= 1, "goal_retry.max_total_iterations", ">= 1");
  CheckExactZoneOptions(o.exact_zones);
  CheckBaseEscapeOptions(o.base_escape);
  CheckArmDwellOptions(o.arm_dwell);
}

}  // namespace topay
