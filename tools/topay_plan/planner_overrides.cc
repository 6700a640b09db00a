#include "tools/topay_plan/planner_overrides.h"

namespace topay::plan {

BaseLimitChoice ApplyPlannerOverrides(const PlannerOverrides& overrides, const RobotModel& model,
                                      WholeBodyPlannerOptions* options) {
  if (overrides.num_threads) {
    options->num_threads = *overrides.num_threads;
    options->front_end.num_threads = *overrides.num_threads;
  }
  if (overrides.time_limit_s) options->time_limit_s = *overrides.time_limit_s;
  if (overrides.sequential) options->sequential = *overrides.sequential;
  if (overrides.optimizer_time_limit_s) {
    options->optimizer.time_limit_s = *overrides.optimizer_time_limit_s;
  }
  if (overrides.acquisition_budget_s) {
    options->front_end.acquisition_budget_s = *overrides.acquisition_budget_s;
  }
  const BaseLimitChoice choice = BaseLimitChoiceInForce(overrides.base_limits, options->base_limits);
  options->base_limits = ChooseBaseLimits(choice, model, options->base_limits);
  return choice;
}

}  // namespace topay::plan
