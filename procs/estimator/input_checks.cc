#include "procs/estimator/input_checks.h"

#include <cmath>

namespace topay::estimator {

const char* InputFaultName(InputFault fault) {
  switch (fault) {
    case InputFault::kPoseNotFinite: return "BASE_POSE not finite";
    case InputFault::kPoseOutOfOrder: return "BASE_POSE out of order";
    case InputFault::kPoseTooOld: return "BASE_POSE too old";
    case InputFault::kPoseFuture: return "BASE_POSE stamped in the future";
    case InputFault::kVelocityNotFinite: return "BASE_VELOCITY not finite";
    case InputFault::kVelocityOutOfOrder: return "BASE_VELOCITY out of order";
    case InputFault::kVelocityTooOld: return "BASE_VELOCITY too old";
    case InputFault::kVelocityFuture: return "BASE_VELOCITY stamped in the future";
    case InputFault::kVelocityImplausible: return "BASE_VELOCITY beyond the fastest odometry believed";
    case InputFault::kJointsMalformed: return "JOINT_STATE arrays do not match num_joints";
    case InputFault::kJointsCount: return "JOINT_STATE wrong joint count";
    case InputFault::kJointsNotFinite: return "JOINT_STATE not finite";
    case InputFault::kJointsOutOfOrder: return "JOINT_STATE out of order";
    case InputFault::kJointsFuture: return "JOINT_STATE stamped in the future";
    case InputFault::kJointsJump: return "JOINT_STATE jump beyond the joint rate limit";
    case InputFault::kGripperMalformed: return "GRIPPER_STATE without a joint 'gripper'";
    case InputFault::kGripperRange: return "GRIPPER_STATE position not in [0, 1]";
    case InputFault::kGripperOutOfOrder: return "GRIPPER_STATE out of order";
    case InputFault::kGripperFuture: return "GRIPPER_STATE stamped in the future";
  }
  return "?";
}

std::optional<InputFault> CheckPose(const base_pose_t& msg) {
  if (!std::isfinite(msg.x_m) || !std::isfinite(msg.y_m) || !std::isfinite(msg.yaw_rad)) {
    return InputFault::kPoseNotFinite;
  }
  return std::nullopt;
}

std::optional<InputFault> CheckVelocity(const base_velocity_t& msg, double max_speed_mps, double max_yaw_rate_radps) {
  if (!std::isfinite(msg.v_mps) || !std::isfinite(msg.omega_radps)) return InputFault::kVelocityNotFinite;
  if (std::abs(msg.v_mps) > max_speed_mps || std::abs(msg.omega_radps) > max_yaw_rate_radps) {
    return InputFault::kVelocityImplausible;
  }
  return std::nullopt;
}

namespace {

bool ArraysMatch(const joint_state_t& msg) {
  const auto n = static_cast<std::size_t>(msg.num_joints);
  return msg.num_joints >= 0 && msg.names.size() == n && msg.position_rad.size() == n &&
         msg.velocity_radps.size() == n && (msg.effort_Nm.size() == n || msg.effort_Nm.empty());
}

}  // namespace

std::optional<InputFault> CheckJoints(const joint_state_t& msg, int expected_joints) {
  if (!ArraysMatch(msg)) return InputFault::kJointsMalformed;
  if (expected_joints > 0 && msg.num_joints != expected_joints) return InputFault::kJointsCount;
  for (int j = 0; j < msg.num_joints; ++j) {
    if (!std::isfinite(msg.position_rad[j]) || !std::isfinite(msg.velocity_radps[j])) {
      return InputFault::kJointsNotFinite;
    }
  }
  return std::nullopt;
}

std::optional<InputFault> GripperPosition(const joint_state_t& msg, double* position) {
  if (!ArraysMatch(msg)) return InputFault::kGripperMalformed;
  for (int j = 0; j < msg.num_joints; ++j) {
    if (msg.names[j] != "gripper") continue;
    const double p = msg.position_rad[j];
    if (!std::isfinite(p) || p < 0.0 || p > 1.0) return InputFault::kGripperRange;
    *position = p;
    return std::nullopt;
  }
  return InputFault::kGripperMalformed;
}

}  // namespace topay::estimator
