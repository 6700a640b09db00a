#include "sim/motors/stalled_plant.h"

#include <algorithm>
#include <cmath>

namespace topay::sim::motors {

std::string CheckStalledPlantOptions(const StalledPlantOptions& options) {
  if (!(options.stale_after_s > 0.0 && std::isfinite(options.stale_after_s))) return "stale_after_s must be > 0";
  if (!(options.carry_on_s >= 0.0 && std::isfinite(options.carry_on_s))) return "carry_on_s must be >= 0";
  return "";
}

void StalledPlant::OnPlantState(const PlantState& state, double time_s) {
  latest_ = state;
  received_s_ = time_s;
  carried_.reset();
}

const PlantState* StalledPlant::At(double time_s, const ActuatorCommand& command) {
  if (!latest_) return nullptr;
  const double dt_s = std::max(0.0, time_s - last_time_s_);
  last_time_s_ = std::max(last_time_s_, time_s);
  const double age_s = time_s - received_s_;
  counts_.longest_stall_s = std::max(counts_.longest_stall_s, age_s);
  if (age_s <= options_.stale_after_s) return &*latest_;
  if (!carried_) {
    ++counts_.stalls;
    carried_ = latest_;
    carried_time_s_ = received_s_;
  }
  const double carry_end_s = received_s_ + options_.carry_on_s;
  if (time_s > carry_end_s) {
    Carry(carry_end_s, command);
    carried_->v_mps = carried_->omega_radps = 0.0;  // the simulator's world paused
    carried_->qdot_radps.setZero();
    counts_.held_s += std::min(dt_s, time_s - carry_end_s);
  } else {
    Carry(time_s, command);
  }
  return &*carried_;
}

void StalledPlant::Carry(double end_s, const ActuatorCommand& command) {
  const double dt_s = end_s - carried_time_s_;
  if (!(dt_s > 0.0)) return;
  carried_time_s_ = end_s;
  counts_.carried_s += dt_s;
  PlantState& s = *carried_;
  // A command the drives give is finite (they clamp it); anything else holds the robot still.
  const bool base_ok = std::isfinite(command.v_mps) && std::isfinite(command.omega_radps);
  s.v_mps = base_ok ? command.v_mps : 0.0;
  s.omega_radps = base_ok ? command.omega_radps : 0.0;
  // The unicycle over dt at its midpoint heading.
  const double yaw_mid = s.state.yaw_rad + 0.5 * s.omega_radps * dt_s;
  s.state.x_m += s.v_mps * std::cos(yaw_mid) * dt_s;
  s.state.y_m += s.v_mps * std::sin(yaw_mid) * dt_s;
  s.state.yaw_rad += s.omega_radps * dt_s;
  const bool joints_ok = command.qdot_radps.size() == s.qdot_radps.size() &&
                         s.state.q_rad.size() == s.qdot_radps.size() && command.qdot_radps.allFinite();
  if (joints_ok) {
    s.qdot_radps = command.qdot_radps;
    s.state.q_rad += s.qdot_radps * dt_s;
  } else {
    s.qdot_radps.setZero();
  }
}

}  // namespace topay::sim::motors
