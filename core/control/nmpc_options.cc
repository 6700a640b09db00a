#include "core/control/nmpc_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

void Fail(const char* field, double value, const char* requirement) {
  throw std::invalid_argument(std::string("NmpcOptions: ") + field + " must be " + requirement +
                              ", got " + std::to_string(value));
}

void CheckPositive(double value, const char* field) {
  if (!std::isfinite(value) || value <= 0.0) Fail(field, value, "finite and > 0");
}

void CheckNonNegative(double value, const char* field) {
  if (!std::isfinite(value) || value < 0.0) Fail(field, value, "finite and >= 0");
}

}  // namespace

void NmpcOptions::Check() const {
  if (horizon_steps < 2 || horizon_steps > 200) {
    Fail("horizon_steps", horizon_steps, "in [2, 200]");
  }
  CheckPositive(step_s, "step_s");
  CheckPositive(control_period_s, "control_period_s");
  if (control_period_s > step_s) Fail("control_period_s", control_period_s, "<= step_s");
  CheckNonNegative(latency_s, "latency_s");
  CheckPositive(time_budget_s, "time_budget_s");
  if (max_iterations < 1) Fail("max_iterations", max_iterations, ">= 1");
  CheckPositive(position_weight, "position_weight");
  CheckPositive(yaw_weight, "yaw_weight");
  CheckPositive(joint_weight, "joint_weight");
  if (!std::isfinite(terminal_weight_factor) || terminal_weight_factor < 1.0) {
    Fail("terminal_weight_factor", terminal_weight_factor, "finite and >= 1");
  }
  CheckPositive(v_weight, "v_weight");
  CheckPositive(omega_weight, "omega_weight");
  CheckPositive(qd_weight, "qd_weight");
  CheckNonNegative(a_weight, "a_weight");
  CheckNonNegative(beta_weight, "beta_weight");
  CheckNonNegative(qdd_weight, "qdd_weight");
  CheckPositive(limit_weight, "limit_weight");
  CheckPositive(stale_state_s, "stale_state_s");
  CheckNonNegative(end_settle_s, "end_settle_s");
}

}  // namespace topay
