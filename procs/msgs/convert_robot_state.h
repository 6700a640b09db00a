#pragma once
// robot_state_t <-> the core's whole-body state plus the measured velocities.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/robot/whole_body_state.h"
#include "topay/robot_state_t.hpp"

namespace topay::msgs {

/// A whole-robot state estimate in core types: X_WB and q (WholeBodyState), the base velocity
/// in B, the joint rates, the gripper. Joint efforts are not carried (NaN on the wire).
struct RobotStateEstimate {
  std::int64_t utime = 0;            ///< time of the estimate, us since the Unix epoch
  WholeBodyState state;              ///< x, y, yaw (X_WB in SE(2)) and q, m and rad
  double v_mps = 0.0;                ///< forward speed along B's x axis, m/s
  double omega_radps = 0.0;          ///< yaw rate, rad/s
  Eigen::VectorXd qdot_radps;        ///< joint rates, same size as state.q_rad
  std::vector<std::string> joint_names;  ///< URDF names, same size as q (empty: "joint<i>")
  double gripper = 0.0;              ///< 0 open .. 1 closed (NaN if none)
};

/// Encodes every field; pose and velocity carry utime as their own time.
robot_state_t ToMessage(const RobotStateEstimate& estimate);

/// Decodes a message; nullopt with *error (naming the field) if its arrays disagree with
/// num_joints or a pose, velocity or joint value is not finite.
std::optional<RobotStateEstimate> FromMessage(const robot_state_t& msg, std::string* error);

}  // namespace topay::msgs
