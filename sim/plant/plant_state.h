#pragma once
// What the plant is (ground truth) and what its drives measure (encoders).

#include <cstdint>

#include <Eigen/Core>

#include "core/robot/whole_body_state.h"

namespace topay::sim {

/// The true state of the robot: X_WB and q, the true base velocity (wheel slip included), the
/// joint rates and the gripper.
struct PlantState {
  WholeBodyState state;
  double v_mps = 0.0;          ///< true forward speed of B, m/s
  double omega_radps = 0.0;    ///< true yaw rate, rad/s
  Eigen::VectorXd qdot_radps;  ///< joint rates, rad/s
  double gripper = 0.0;        ///< 0 open .. 1 closed
};

/// What the drives' encoders measure: wheel rates and angles (no slip: the wheels turn as
/// driven), the base velocity they imply (wheel odometry), the joints, the gripper.
struct MeasuredActuators {
  double wheel_left_radps = 0.0, wheel_right_radps = 0.0;  ///< wheel rates, rad/s (positive: forward)
  double wheel_left_rad = 0.0, wheel_right_rad = 0.0;      ///< wheel angles since the start, rad
  double v_mps = 0.0;          ///< forward speed from the wheels, m/s
  double omega_radps = 0.0;    ///< yaw rate from the wheels, rad/s
  Eigen::VectorXd q_rad;       ///< joint positions, rad
  Eigen::VectorXd qdot_radps;  ///< joint rates, rad/s
  double gripper = 0.0;        ///< gripper position, 0 open .. 1 closed
  bool braking = false;        ///< the base drives are braking (command lost or rejected)
};

/// Counters of the plant since it started.
struct PlantCounts {
  std::int64_t steps = 0;
  std::int64_t commands_accepted = 0;
  std::int64_t commands_rejected = 0;  ///< non-finite values or a wrong joint count
  std::int64_t command_timeouts = 0;   ///< times the drives started braking for lack of commands
};

}  // namespace topay::sim
