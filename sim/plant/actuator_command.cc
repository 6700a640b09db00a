#include "sim/plant/actuator_command.h"

#include <cmath>

namespace topay::sim {

std::string CheckActuatorCommand(const ActuatorCommand& command, int num_joints) {
  if (command.qdot_radps.size() != num_joints) {
    return std::to_string(command.qdot_radps.size()) + " joint rates for a robot with " +
           std::to_string(num_joints) + " joints";
  }
  if (!std::isfinite(command.v_mps)) return "v_mps is not finite";
  if (!std::isfinite(command.omega_radps)) return "omega_radps is not finite";
  for (int i = 0; i < num_joints; ++i) {
    if (!std::isfinite(command.qdot_radps[i])) return "qdot_radps[" + std::to_string(i) + "] is not finite";
  }
  if (!std::isfinite(command.gripper) || command.gripper < 0.0 || command.gripper > 1.0) {
    return "gripper must be in [0, 1]";
  }
  return "";
}

}  // namespace topay::sim
