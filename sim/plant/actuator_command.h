#pragma once
// The actuator interface of the plant: what the drives are told (base speed and yaw rate, joint
// rates, gripper target). CONTROL_COMMAND is converted into it today; a motor-controller
// simulator (the CAN issue) will produce it instead. The plant knows no LCM.

#include <string>

#include <Eigen/Core>

namespace topay::sim {

struct ActuatorCommand {
  double v_mps = 0.0;          ///< base forward speed along B's x, m/s
  double omega_radps = 0.0;    ///< base yaw rate, rad/s
  Eigen::VectorXd qdot_radps;  ///< joint rates q1..qN, rad/s (N = the robot's joint count)
  double gripper = 0.0;        ///< gripper target, 0 open .. 1 closed
};

/// Empty if `command` fits a robot with `num_joints` joints and every value is finite (gripper
/// in [0, 1]); else the reason, e.g. "qdot_radps[3] is not finite".
std::string CheckActuatorCommand(const ActuatorCommand& command, int num_joints);

}  // namespace topay::sim
