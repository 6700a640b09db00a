#pragma once
// The base's wheel controller as a CAN node (docs/base_protocol.md, docs/motorsim.md): the
// drive side of the base protocol over the plant's motion. It takes mode requests and velocity
// commands addressed to its node id (checksum, complement, ranges and the rolling counter
// checked by drivers/base; refusals counted), runs the controller's mode state machine with its
// own command watchdog (no valid command for command_timeout_s in CAN command mode -> quick
// stop: the wheels brake to zero), and sends status at 20 Hz and at once on a mode change, wheel
// speeds and odometry ticks at 100 Hz (from the plant's v, omega through the drive's
// kinematics) and a fault frame when a fault is raised. Pure: times are passed in.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drivers/base/base_mode.h"
#include "drivers/base/diff_drive_kinematics.h"
#include "drivers/base/fault_codes.h"
#include "drivers/base/mode_state_machine.h"
#include "drivers/can/can_frame.h"

namespace topay::sim::motors {

struct WheelControllerOptions {
  /// The controller's node id (1..127). Default 16: the arm's drives are nodes 1..7 on the same
  /// bus and the base protocol's ids (function base + node) would clash with theirs at 1..7.
  int node_id = 16;
  base::DriveGeometry geometry;              ///< wheel radius 0.1 m, track 0.5 m, 16384 ticks/rev
  /// Watchdog 0.05 s (ten 5 ms bridge cycles, as the arm drives' RPDO deadline: a dead bridge has
  /// the whole robot braking within about 60 ms), timeout -> quick stop.
  base::ModeStateMachineOptions modes{.command_timeout_s = 0.05};
  double status_period_s = 0.05;             ///< status frame period (20 Hz), s
  double feedback_period_s = 0.01;           ///< wheel speeds + odometry period (100 Hz), s
  double battery_voltage_v = 48.0;           ///< reported in the status frame, V
  double max_wheel_speed_radps = 30.0;       ///< the motors' top speed (both wheels scaled together), rad/s
  double quick_stop_decel_mps2 = 1.0;        ///< quick stop ramp of v, m/s^2
  double quick_stop_decel_radps2 = 2.0;      ///< quick stop ramp of omega, rad/s^2
};

/// Empty when the options are valid, else what is wrong.
std::string CheckWheelControllerOptions(const WheelControllerOptions& options);

struct WheelControllerCounts {
  std::int64_t mode_requests = 0;      ///< accepted
  std::int64_t mode_refused = 0;       ///< valid frames the state machine refused
  std::int64_t commands = 0;           ///< velocity commands followed
  std::int64_t commands_ignored = 0;   ///< valid commands outside CAN command mode
  std::int64_t malformed = 0;          ///< our ids, refused by a decoder (checksum, range, stale, DLC)
  std::int64_t counter_gaps = 0;       ///< velocity commands lost, from the rolling counter
  std::int64_t timeouts = 0;           ///< command watchdog trips
  std::int64_t faults = 0;             ///< faults raised
  std::int64_t frames_sent = 0;
};

class WheelControllerNode {
 public:
  /// `options` must pass CheckWheelControllerOptions (else std::invalid_argument).
  WheelControllerNode(const WheelControllerOptions& options, double start_time_s);

  /// A frame from the bus at time_s. True when it was one of this node's host -> base frames
  /// (handled or refused), false for every other frame (ignored).
  bool OnFrame(const can::CanFrame& frame, double time_s);

  /// Raises `fault` at time_s (fault injection): fault mode, a fault frame at the next Step.
  void RaiseFault(base::BaseFault fault, double time_s);

  /// Advances to time_s: the watchdog, the quick-stop ramp, the wheel angles from the plant's
  /// v, omega (null: not known yet: no feedback frames), and appends the frames due to *out.
  void Step(double time_s, const std::optional<base::UnicycleVelocity>& plant, std::vector<can::CanFrame>* out);

  /// What the wheels are driven at now (the plant's base command).
  base::UnicycleVelocity command() const { return output_; }
  base::BaseMode mode() const { return modes_.mode(); }
  const base::ModeStateMachine& modes() const { return modes_; }
  const WheelControllerCounts& counts() const;
  const std::string& last_error() const { return last_error_; }
  int node_id() const { return options_.node_id; }

 private:
  void OnModeRequest(const can::CanFrame& frame, double time_s);
  void OnVelocityCommand(const can::CanFrame& frame, double time_s);
  void UpdateOutput(double dt_s);
  void IntegrateWheels(double dt_s, const base::UnicycleVelocity& plant);
  void SendStatus(std::vector<can::CanFrame>* out);
  void SendFeedback(const base::UnicycleVelocity& plant, std::vector<can::CanFrame>* out);
  void Emit(const std::optional<can::CanFrame>& frame, const std::string& error, std::vector<can::CanFrame>* out);

  WheelControllerOptions options_;
  base::ModeStateMachine modes_;
  mutable WheelControllerCounts counts_;
  std::string last_error_;
  base::UnicycleVelocity target_;   // last followed command (clamped)
  base::UnicycleVelocity output_;   // what the wheels drive
  std::optional<std::uint8_t> last_command_counter_;
  std::optional<base::BaseFault> fault_to_report_;
  std::optional<base::BaseMode> reported_mode_;
  double last_step_s_;
  double next_status_s_;
  double next_feedback_s_;
  double left_rad_ = 0.0, right_rad_ = 0.0;  // wheel angles since the start
  std::uint8_t status_counter_ = 0, speeds_counter_ = 0, odometry_counter_ = 0, fault_counter_ = 0;
};

}  // namespace topay::sim::motors
