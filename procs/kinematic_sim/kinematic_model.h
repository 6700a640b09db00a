#pragma once
// The robot model of the first simulation graph: a differential-drive base integrated from
// velocity commands (unicycle, zero-order hold) and arm joints integrated from joint-rate
// commands. Event driven and clock free: the state advances by the commands' own utimes, so
// replaying the same commands reproduces the same states bit for bit.

#include <cstdint>
#include <string>
#include <vector>

#include "procs/msgs/convert_robot_state.h"
#include "topay/control_command_t.hpp"

namespace topay::kinsim {

struct KinematicModelOptions {
  double x_m = 0.0, y_m = 0.0, yaw_rad = 0.0;  ///< initial X_WB (SE(2)), m and rad
  std::vector<double> q_rad = std::vector<double>(7, 0.0);  ///< initial joints (7), rad
  std::vector<std::string> joint_names;       ///< URDF names (empty: joint1..jointN)
  double max_step_s = 0.1;   ///< longest integration step between two commands, s
  double state_rate_hz = 10.0;  ///< ROBOT_STATE while no command arrives (0: only on commands)
};

/// Loads options from YAML (keys as the struct's fields; every key optional). Throws
/// std::runtime_error naming the file and field for an unreadable file, an unknown key or a
/// wrong value.
KinematicModelOptions LoadKinematicModelOptions(const std::string& path);

class KinematicModel {
 public:
  explicit KinematicModel(const KinematicModelOptions& options);

  /// Largest accepted |rate| of a command (m/s, rad/s): far above any robot's, far below what
  /// overflows the state when integrated.
  static constexpr double kMaxRate = 1e3;

  /// Advances to cmd.utime under the previous command (min(dt, max_step_s); nothing before the
  /// first command or for a command older than the last), then holds `cmd`. Returns false
  /// (state unchanged) for a command whose joint count differs from the model's, that is not
  /// finite, or with a rate beyond kMaxRate.
  bool Apply(const control_command_t& cmd);

  /// The state at the last command's time (or `utime` before any command).
  const msgs::RobotStateEstimate& state() const { return state_; }
  std::int64_t commands_applied() const { return commands_; }

 private:
  msgs::RobotStateEstimate state_;
  double max_step_s_;
  std::int64_t last_utime_ = -1;
  std::int64_t commands_ = 0;
};

}  // namespace topay::kinsim
