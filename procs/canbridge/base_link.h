#pragma once
// The host side of the base controller's protocol (docs/base_protocol.md): the mode the bridge
// wants the base in (CAN command to move, quick stop to stop) reached through the mode state
// machine's allowed requests and repeated until the status shows it, the velocity command with
// its rolling counter every cycle, and the feedback (status, wheel speeds, odometry, faults).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drivers/base/base_mode.h"
#include "drivers/base/diff_drive_kinematics.h"
#include "drivers/can/can_frame.h"
#include "procs/canbridge/canbridge_options.h"
#include "procs/canbridge/frame_result.h"

namespace topay::canbridge {

class BaseLink {
 public:
  explicit BaseLink(const BaseLinkOptions& options);

  /// Decodes `frame` if it is one of this node's ids; *error says what was wrong when malformed.
  FrameResult Handle(const can::CanFrame& frame, double now_s, std::string* error);

  /// The mode the bridge wants: kCanCommand (enabling, running) or kQuickStop (stopped, fault).
  void SetTargetMode(base::BaseMode target) { target_ = target; }
  /// Allows one fault reset request while the base reports fault (DRIVE_COMMAND FAULT_RESET).
  void ArmFaultReset() { fault_reset_armed_ = true; }

  /// The frames of this cycle: a mode request when one is due (the next allowed step towards the
  /// target, repeated every mode_request_repeat_s), then the velocity command (v, omega),
  /// appended to *out (the node reuses one vector every cycle).
  void CycleFrames(double now_s, double v_mps, double omega_radps, std::vector<can::CanFrame>* out);
  /// Only the velocity command (sent at once on a new CONTROL_COMMAND).
  can::CanFrame VelocityFrame(double v_mps, double omega_radps);

  std::optional<base::BaseMode> mode() const { return mode_; }
  bool at_target() const { return mode_ == target_; }
  std::uint16_t fault_bits() const { return fault_bits_; }
  bool faulted() const { return mode_ == base::BaseMode::kFault || fault_bits_ != 0; }
  double battery_v() const { return battery_v_; }
  /// Seconds since the last status, -1 before the first.
  double status_age_s(double now_s) const { return last_status_s_ ? now_s - *last_status_s_ : -1.0; }
  bool status_seen() const { return last_status_s_.has_value(); }
  /// True when a status was seen and none came for status_timeout_s.
  bool lost(double now_s) const { return last_status_s_ && now_s - *last_status_s_ > options_.status_timeout_s; }
  /// The unicycle velocity of the last wheel speeds, and whether a new one came since the last call.
  std::optional<base::UnicycleVelocity> TakeNewVelocity();
  std::int64_t velocity_frames_sent() const { return velocity_frames_sent_; }
  int node_id() const { return options_.node_id; }

 private:
  std::optional<base::ModeRequest> NextRequest() const;

  BaseLinkOptions options_;
  base::BaseMode target_ = base::BaseMode::kStandby;
  std::optional<base::BaseMode> mode_;
  std::uint16_t fault_bits_ = 0;
  double battery_v_ = 0.0;
  std::optional<double> last_status_s_;
  bool fault_reset_armed_ = false;
  std::optional<base::ModeRequest> last_request_;
  double last_request_s_ = -1e9;
  std::uint8_t counter_ = 0;
  std::optional<std::uint8_t> last_odometry_counter_;
  std::optional<base::UnicycleVelocity> new_velocity_;
  std::int64_t velocity_frames_sent_ = 0;
};

}  // namespace topay::canbridge
