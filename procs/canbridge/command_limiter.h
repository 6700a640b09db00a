#pragma once
// The bridge's last line of defence on commands: every command that goes to the bus is within
// the robot's limits (|v|, |omega|, |qdot|) and changes from the previous one sent by no more
// than the acceleration limits allow over the time between them (at most one cycle), whatever
// CONTROL_COMMAND said. Non-finite or misshapen commands are rejected before they get here.

#include <string>
#include <vector>

#include "core/robot/robot_model.h"
#include "topay/control_command_t.hpp"

namespace topay::canbridge {

/// The limits the bridge enforces (from the robot description).
struct CommandLimits {
  double v_max_mps = 1.0;
  double a_max_mps2 = 0.8;
  double omega_max_radps = 0.9;
  double beta_max_radps2 = 1.0;
  std::vector<double> qd_max_radps;    ///< Per joint.
  std::vector<double> qdd_max_radps2;  ///< Per joint.
};

/// base_limits and joint_limits of `model`.
CommandLimits CommandLimitsOf(const RobotModel& model);

/// One velocity command for the devices (SI units).
struct DeviceCommand {
  double v_mps = 0.0;
  double omega_radps = 0.0;
  std::vector<double> qdot_radps;
};

/// Empty when `msg` can be commanded: num_joints equal to `num_joints` and to the array's size,
/// v, omega and every qdot finite. Else why not, e.g. "qdot_radps[2] is nan".
std::string CheckControlCommand(const control_command_t& msg, int num_joints);

/// The command of a checked message.
DeviceCommand ToDeviceCommand(const control_command_t& msg);

/// True when |v|, |omega| and every |qdot| are <= tolerance.
bool IsZeroCommand(const DeviceCommand& command, double tolerance);

class CommandLimiter {
 public:
  /// `cycle_period_s` bounds the time one step may use for its change. Throws
  /// std::invalid_argument when the joint limit lists differ in size or a limit is not > 0.
  CommandLimiter(CommandLimits limits, double cycle_period_s);

  /// The command to send at `now_s` towards `target`: each value clamped to its limit, then
  /// its change from the last one sent limited to accel * min(now_s - last step, cycle period).
  /// Counts a clamp when any value was changed. `target` must have the limits' joint count.
  const DeviceCommand& Step(const DeviceCommand& target, double now_s);

  /// The next step starts from zero (after a stop: the devices quick-stopped to rest).
  void ResetToZero(double now_s);

  const DeviceCommand& last() const { return last_; }
  long clamp_count() const { return clamp_count_; }
  const CommandLimits& limits() const { return limits_; }

 private:
  double Limit(double target, double previous, double max_abs, double max_rate, double dt_s, bool* clamped) const;

  CommandLimits limits_;
  double cycle_period_s_;
  DeviceCommand last_;
  double last_time_s_ = 0.0;
  bool has_time_ = false;
  long clamp_count_ = 0;
};

}  // namespace topay::canbridge
