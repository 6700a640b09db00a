#include "core/control/nmpc_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/option_checks.h"

namespace topay {
namespace {
constexpr const char* kNmpcOptions = "NmpcOptions";  // the owner in error messages
}  // namespace

void NmpcOptions::Check() const {
  if (horizon_steps < 2 || horizon_steps > 200) {
    FailOption(kNmpcOptions, "horizon_steps", horizon_steps, "in [2, 200]");
  }
  CheckOptionPositive(kNmpcOptions, "step_s", step_s);
  CheckOptionPositive(kNmpcOptions, "control_period_s", control_period_s);
  if (control_period_s > step_s) FailOption(kNmpcOptions, "control_period_s", control_period_s, "<= step_s");
  CheckOptionNonNegative(kNmpcOptions, "latency_s", latency_s);
  CheckOptionPositive(kNmpcOptions, "time_budget_s", time_budget_s);
  if (max_iterations < 1) FailOption(kNmpcOptions, "max_iterations", max_iterations, ">= 1");
  CheckOptionPositive(kNmpcOptions, "position_weight", position_weight);
  CheckOptionPositive(kNmpcOptions, "cross_track_weight", cross_track_weight);
  CheckOptionPositive(kNmpcOptions, "yaw_weight", yaw_weight);
  CheckOptionPositive(kNmpcOptions, "joint_weight", joint_weight);
  if (!std::isfinite(terminal_weight_factor) || terminal_weight_factor < 1.0) {
    FailOption(kNmpcOptions, "terminal_weight_factor", terminal_weight_factor, "finite and >= 1");
  }
  CheckOptionPositive(kNmpcOptions, "v_weight", v_weight);
  CheckOptionPositive(kNmpcOptions, "omega_weight", omega_weight);
  CheckOptionPositive(kNmpcOptions, "qd_weight", qd_weight);
  CheckOptionNonNegative(kNmpcOptions, "a_weight", a_weight);
  CheckOptionNonNegative(kNmpcOptions, "beta_weight", beta_weight);
  CheckOptionNonNegative(kNmpcOptions, "qdd_weight", qdd_weight);
  CheckOptionPositive(kNmpcOptions, "limit_weight", limit_weight);
  CheckOptionPositive(kNmpcOptions, "stale_state_s", stale_state_s);
  CheckOptionNonNegative(kNmpcOptions, "end_settle_s", end_settle_s);
  arm_pacing.Check();
}

}  // namespace topay
