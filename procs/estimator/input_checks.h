#pragma once
// The checks of topay-estimator's inputs before they reach the filter: every kind of bad input
// has a name (counted and logged once per kind by the node).

#include <array>
#include <cstdint>
#include <optional>

#include "topay/base_pose_t.hpp"
#include "topay/base_velocity_t.hpp"
#include "topay/joint_state_t.hpp"

namespace topay::estimator {

enum class InputFault : std::int8_t {
  kPoseNotFinite,
  kPoseOutOfOrder,      ///< stamp not after the previous BASE_POSE's
  kPoseTooOld,          ///< older than the filter's history (max_delay_s)
  kPoseFuture,          ///< stamped after now + max_future_s
  kVelocityNotFinite,
  kVelocityOutOfOrder,  ///< stamp not after the previous BASE_VELOCITY's (dt <= 0)
  kVelocityTooOld,
  kVelocityFuture,
  kVelocityImplausible, ///< |v| or |omega| beyond the fastest odometry believed (a corrupted message)
  kJointsMalformed,     ///< arrays do not match num_joints
  kJointsCount,         ///< not the robot's joint count
  kJointsNotFinite,     ///< a position or velocity NaN or infinite
  kJointsOutOfOrder,    ///< stamp not after the previous JOINT_STATE's
  kJointsFuture,
  kJointsJump,          ///< moved farther than the joint rate limit allows (continuity gate)
  kGripperMalformed,    ///< no joint named "gripper", or arrays that do not match
  kGripperRange,        ///< position not finite or not in [0, 1]
  kGripperOutOfOrder,
  kGripperFuture,
};
inline constexpr int kNumInputFaults = 19;

/// A short name, e.g. "BASE_POSE not finite".
const char* InputFaultName(InputFault fault);

/// Per kind counts.
using FaultCounts = std::array<std::int64_t, kNumInputFaults>;

std::optional<InputFault> CheckPose(const base_pose_t& msg);
/// Finite, and |v| <= max_speed_mps and |omega| <= max_yaw_rate_radps (the fastest odometry
/// believed: a bit-flipped BASE_VELOCITY with omega 235 rad/s turned the estimate 2.35 rad in
/// 10 ms, finding 27).
std::optional<InputFault> CheckVelocity(const base_velocity_t& msg, double max_speed_mps, double max_yaw_rate_radps);
/// Arrays of num_joints entries (efforts: num_joints or none), positions and velocities
/// finite, and `expected_joints` joints unless it is 0.
std::optional<InputFault> CheckJoints(const joint_state_t& msg, int expected_joints);
/// The position of the joint named "gripper" in [0, 1], or the fault.
std::optional<InputFault> GripperPosition(const joint_state_t& msg, double* position);

}  // namespace topay::estimator
