#include "procs/msgs/convert_robot_state.h"

#include <cmath>
#include <limits>

namespace topay::msgs {

robot_state_t ToMessage(const RobotStateEstimate& estimate) {
  const int n = estimate.state.num_joints();
  robot_state_t msg;
  msg.utime = estimate.utime;
  msg.pose.utime = estimate.utime;
  msg.pose.x_m = estimate.state.x_m;
  msg.pose.y_m = estimate.state.y_m;
  msg.pose.yaw_rad = estimate.state.yaw_rad;
  msg.velocity.utime = estimate.utime;
  msg.velocity.v_mps = estimate.v_mps;
  msg.velocity.omega_radps = estimate.omega_radps;
  msg.joints.utime = estimate.utime;
  msg.joints.num_joints = n;
  for (int j = 0; j < n; ++j) {
    msg.joints.names.push_back(j < static_cast<int>(estimate.joint_names.size())
                                   ? estimate.joint_names[j]
                                   : "joint" + std::to_string(j + 1));
    msg.joints.position_rad.push_back(estimate.state.q_rad(j));
    msg.joints.velocity_radps.push_back(j < estimate.qdot_radps.size() ? estimate.qdot_radps(j)
                                                                       : 0.0);
    msg.joints.effort_Nm.push_back(std::numeric_limits<double>::quiet_NaN());
  }
  msg.gripper = estimate.gripper;
  return msg;
}

std::optional<RobotStateEstimate> FromMessage(const robot_state_t& msg, std::string* error) {
  const joint_state_t& joints = msg.joints;
  const auto n = static_cast<std::size_t>(std::max(joints.num_joints, 0));
  if (joints.num_joints < 0 || joints.names.size() != n || joints.position_rad.size() != n ||
      joints.velocity_radps.size() != n) {
    *error = "robot_state_t.joints: arrays do not match num_joints";
    return std::nullopt;
  }
  if (!std::isfinite(msg.pose.x_m) || !std::isfinite(msg.pose.y_m) ||
      !std::isfinite(msg.pose.yaw_rad)) {
    *error = "robot_state_t.pose: not finite";
    return std::nullopt;
  }
  if (!std::isfinite(msg.velocity.v_mps) || !std::isfinite(msg.velocity.omega_radps)) {
    *error = "robot_state_t.velocity: not finite";
    return std::nullopt;
  }
  RobotStateEstimate estimate;
  estimate.utime = msg.utime;
  estimate.state.x_m = msg.pose.x_m;
  estimate.state.y_m = msg.pose.y_m;
  estimate.state.yaw_rad = msg.pose.yaw_rad;
  estimate.state.q_rad = Eigen::Map<const Eigen::VectorXd>(joints.position_rad.data(), n);
  estimate.qdot_radps = Eigen::Map<const Eigen::VectorXd>(joints.velocity_radps.data(), n);
  if (!estimate.state.IsFinite() || !estimate.qdot_radps.allFinite()) {
    *error = "robot_state_t.joints: positions or velocities not finite";
    return std::nullopt;
  }
  estimate.v_mps = msg.velocity.v_mps;
  estimate.omega_radps = msg.velocity.omega_radps;
  estimate.joint_names = joints.names;
  estimate.gripper = msg.gripper;
  return estimate;
}

}  // namespace topay::msgs
