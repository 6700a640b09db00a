#include "procs/motorsim/motorsim_messages.h"

#include "procs/msgs/convert_robot_state.h"

namespace topay::motorsim {

std::optional<sim::PlantState> PlantStateFromMessage(const robot_state_t& msg, int num_joints, std::string* error) {
  std::optional<msgs::RobotStateEstimate> estimate = msgs::FromMessage(msg, error);
  if (!estimate) return std::nullopt;
  if (estimate->state.q_rad.size() != num_joints) {
    if (error != nullptr) {
      *error = "SIM_PLANT_STATE has " + std::to_string(estimate->state.q_rad.size()) + " joints, the motor simulator " +
               std::to_string(num_joints) + " drives";
    }
    return std::nullopt;
  }
  sim::PlantState state;
  state.state = estimate->state;
  state.v_mps = estimate->v_mps;
  state.omega_radps = estimate->omega_radps;
  state.qdot_radps = estimate->qdot_radps;
  state.gripper = estimate->gripper;
  return state;
}

std::optional<sim::motors::FaultEvent> FaultEventFromMessage(const motorsim_fault_t& msg, std::string* error) {
  using sim::motors::FaultKind;
  sim::motors::FaultEvent event;
  switch (msg.kind) {
    case motorsim_fault_t::CLEAR: event.kind = FaultKind::kClear; break;
    case motorsim_fault_t::DRIVE_FAULT: event.kind = FaultKind::kDriveFault; break;
    case motorsim_fault_t::HEARTBEAT_LOSS: event.kind = FaultKind::kHeartbeatLoss; break;
    case motorsim_fault_t::BUS_OFF: event.kind = FaultKind::kBusOff; break;
    case motorsim_fault_t::RX_LOSS: event.kind = FaultKind::kRxLoss; break;
    case motorsim_fault_t::TX_LOSS: event.kind = FaultKind::kTxLoss; break;
    case motorsim_fault_t::DELAY: event.kind = FaultKind::kDelay; break;
    case motorsim_fault_t::BASE_FAULT: event.kind = FaultKind::kBaseFault; break;
    default:
      if (error != nullptr) *error = "unknown fault kind " + std::to_string(msg.kind);
      return std::nullopt;
  }
  event.joint = msg.joint;
  event.duration_s = msg.duration_s;
  event.value = msg.value;
  event.code = msg.code;
  return event;
}

control_command_t ToActuatorMessage(const sim::ActuatorCommand& command, std::int64_t utime) {
  control_command_t msg;
  msg.utime = utime;
  msg.trajectory_id = 0;
  msg.v_mps = command.v_mps;
  msg.omega_radps = command.omega_radps;
  msg.num_joints = static_cast<std::int32_t>(command.qdot_radps.size());
  msg.qdot_radps.assign(command.qdot_radps.data(), command.qdot_radps.data() + command.qdot_radps.size());
  msg.gripper = 0.0;
  return msg;
}

}  // namespace topay::motorsim
