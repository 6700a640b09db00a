#pragma once
// The robot plant at a fixed step (500 Hz by default): the base as a unicycle driven by (v,
// omega), the joints as integrators of joint rates, the gripper with a stroke time. Each drive
// channel (base, joints, gripper) has a command latency and a first-order lag (plant_options.h),
// then saturates at the robot model's limits: speed and acceleration (BaseLimits, JointLimits)
// and joint positions. The drives have their own watchdog: when no command has reached them
// for command_timeout_s, or a command was rejected, they brake to a stop at their
// deceleration limits (a_max, beta_max, qdd_max). Optional wheel slip (seeded) makes the true
// base motion differ from the wheels' odometry.
//
// Clock free and deterministic: time is the step count; the same options, seed and commands at
// the same steps give the same states bit for bit.

#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "core/common/random.h"
#include "core/robot/robot_model.h"
#include "sim/plant/actuator_command.h"
#include "sim/plant/command_delay.h"
#include "sim/plant/first_order_lag.h"
#include "sim/plant/plant_options.h"
#include "sim/plant/plant_state.h"

namespace topay::sim {

class Plant {
 public:
  /// The model must outlive the plant. options.initial.q_rad must fit it (CheckPlantOptions).
  Plant(const RobotModel& model, const PlantOptions& options, std::uint64_t seed);

  /// Hands `command` to the drives now (it reaches them after each channel's latency). Returns
  /// "" if accepted; else the reason (CheckActuatorCommand): the command is counted as rejected
  /// and the base and joint drives brake from the moment it would have arrived until a valid
  /// command arrives (the gripper keeps its target).
  std::string Command(const ActuatorCommand& command);

  /// Hands a gripper target alone to the gripper drive (it arrives after the gripper latency):
  /// the gripper's own driver, apart from the base and joint drives (their watchdog is not fed).
  /// "" if accepted; else the reason (not finite or outside [0, 1]): ignored, counted as rejected.
  std::string CommandGripper(double target);

  /// Advances one step.
  void Step();

  /// Advances one step to `target` (an ideal follower, topay-sim --follow): the true state is
  /// `target` at the new time, the drives run at its velocities (no lag, no limit, no slip:
  /// the wheels' odometry measures target.v_mps and target.omega_radps), the wheel angles
  /// advance by them over the step. Commands are not applied. `target`'s joint vectors must
  /// fit the model.
  void StepTo(const PlantState& target);

  std::int64_t step_count() const { return step_; }
  double time_s() const { return static_cast<double>(step_) * options_.step_s; }
  double step_s() const { return options_.step_s; }
  const PlantState& state() const { return state_; }
  MeasuredActuators measured() const;
  const PlantCounts& counts() const { return counts_; }
  /// True while the base drives brake (no command, a stale one or a rejected one).
  bool braking() const { return base_braking_; }
  const RobotModel& model() const { return model_; }

 private:
  struct BaseTarget {
    bool brake = true;
    double v_mps = 0.0, omega_radps = 0.0;
  };
  struct JointTarget {
    bool brake = true;
    Eigen::VectorXd qdot_radps;
  };
  void StepBase();
  void StepJoints();
  void StepGripper();

  const RobotModel& model_;
  PlantOptions options_;
  Rng rng_;
  std::int64_t step_ = 0;
  PlantState state_;
  PlantCounts counts_;

  CommandDelay<BaseTarget> base_delay_;
  CommandDelay<JointTarget> joint_delay_;
  CommandDelay<double> gripper_delay_;
  BaseTarget base_target_;
  JointTarget joint_target_;
  double gripper_target_ = 0.0;
  std::int64_t base_rx_step_ = -1;   // step at which the last valid command reached the base drives
  std::int64_t joint_rx_step_ = -1;
  bool base_braking_ = true;
  std::int64_t timeout_steps_;

  FirstOrderLag v_lag_, omega_lag_, joint_lag_;
  double drive_v_mps_ = 0.0, drive_omega_radps_ = 0.0;  // what the wheels drive (before slip)
  double slip_v_ = 0.0, slip_omega_ = 0.0;              // relative slip (Gauss-Markov)
  double slip_decay_ = 0.0, slip_drive_ = 0.0;
  double wheel_left_rad_ = 0.0, wheel_right_rad_ = 0.0;
};

/// The plant's starting joints: options.initial.q_rad, else the model's stow pose, else zeros
/// clamped to the position limits.
Eigen::VectorXd InitialJoints(const RobotModel& model, const PlantOptions& options);

}  // namespace topay::sim
