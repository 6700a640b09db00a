#include "core/planner/whole_body_planner_options.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/common/random.h"

namespace topay {

void CheckWholeBodyPlannerOptions(const WholeBodyPlannerOptions& o) {
  CheckLeadInOptions(o.lead_in);
  auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) {
      throw std::invalid_argument(std::string("WholeBodyPlannerOptions::") + field + " must be " +
                                  rule);
    }
  };
  require(o.early_termination_window_s >= 0.0, "early_termination_window_s",
          ">= 0 (+infinity: wait for every candidate)");
  require(o.num_threads >= 0, "num_threads", ">= 0 (0: all cores)");
  require(o.time_limit_s > 0.0, "time_limit_s", "> 0 (+infinity: no limit)");
  require(o.max_candidates >= 1, "max_candidates", ">= 1");
  require(o.retry.max_rounds >= 1, "retry.max_rounds", ">= 1 (1: no retry)");
  require(o.retry.min_time_left_s >= 0.0, "retry.min_time_left_s", ">= 0");
  require(o.retry.clearance_step_m >= 0.0 && std::isfinite(o.retry.clearance_step_m),
          "retry.clearance_step_m", "finite and >= 0");
  require(o.retry.round_time_share > 0.0 && o.retry.round_time_share <= 1.0,
          "retry.round_time_share", "in (0, 1]");
  require(o.retry.arm_budget_growth >= 1.0 && std::isfinite(o.retry.arm_budget_growth),
          "retry.arm_budget_growth", "finite and >= 1");
  require(o.retry.warm_start_slowdown > 0.0 && o.retry.warm_start_slowdown <= 1.0,
          "retry.warm_start_slowdown", "in (0, 1]");
}

FrontEndOptions RetryRoundFrontEnd(const FrontEndOptions& front_end, const PlanRetryOptions& retry,
                                   int round) {
  constexpr std::uint64_t kRoundSeedSalt = 0x7e7a0000;  // DeriveSeed(seed, salt + round)
  FrontEndOptions out = front_end;
  if (round <= 0) return out;
  const std::uint64_t r = static_cast<std::uint64_t>(round);
  out.seed = DeriveSeed(out.seed, kRoundSeedSalt + r);
  out.ik.seed = DeriveSeed(out.ik.seed, kRoundSeedSalt + r);
  const double growth = std::pow(retry.arm_budget_growth, round);
  out.rrt.time_budget_s *= growth;
  out.rrt.max_iterations = static_cast<std::int64_t>(std::llround(out.rrt.max_iterations * growth));
  return out;
}

}  // namespace topay
