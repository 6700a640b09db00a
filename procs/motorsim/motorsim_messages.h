#pragma once
// topay-motorsim's LCM messages <-> the motor simulator's types: SIM_PLANT_STATE (robot_state_t
// from topay-sim in CAN mode) -> the plant's state, MOTORSIM_FAULT (motorsim_fault_t) -> a
// fault event, and the actuator command -> ACTUATOR_COMMAND (control_command_t).

#include <cstdint>
#include <optional>
#include <string>

#include "sim/motors/fault_injection.h"
#include "sim/plant/actuator_command.h"
#include "sim/plant/plant_state.h"
#include "topay/control_command_t.hpp"
#include "topay/motorsim_fault_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::motorsim {

/// The plant's state in `msg` (pose, the wheels' v and omega, joints and rates, gripper);
/// nullopt with *error for inconsistent arrays or non-finite values, or a joint count other
/// than `num_joints`.
std::optional<sim::PlantState> PlantStateFromMessage(const robot_state_t& msg, int num_joints, std::string* error);

/// The fault a MOTORSIM_FAULT asks for; nullopt with *error for an unknown kind. (Its fields are
/// checked by FaultInjector::Inject.)
std::optional<sim::motors::FaultEvent> FaultEventFromMessage(const motorsim_fault_t& msg, std::string* error);

/// ACTUATOR_COMMAND: v, omega, joint rates at `utime`; trajectory_id 0, gripper 0 (the CAN-mode
/// sim takes the gripper from GRIPPER_COMMAND).
control_command_t ToActuatorMessage(const sim::ActuatorCommand& command, std::int64_t utime);

}  // namespace topay::motorsim
