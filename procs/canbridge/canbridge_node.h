#pragma once
// topay-canbridge's logic (docs/canbridge.md): CONTROL_COMMAND in, CAN frames out every cycle
// (200 Hz) and at once on a new command; CAN feedback in, BASE_VELOCITY, JOINT_STATE and
// DRIVE_STATUS out. It starts the devices (base CAN command mode; drives: NMT, start-up SDOs,
// CiA 402 enable), clamps every command to the robot's limits, stops the robot (zero + quick
// stop) on a stale command, a lost device, bus-off or a device fault, and recovers as documented.
// No LCM and no clock inside: the handlers take the times (seconds on a monotonic clock), so
// tests drive it on a simulated clock; ConnectCanbridgeNode wires it to a ProcessLoop.

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/robot/robot_model.h"
#include "drivers/can/can_bus.h"
#include "procs/canbridge/base_link.h"
#include "procs/canbridge/bridge_state.h"
#include "procs/canbridge/bus_load_meter.h"
#include "procs/canbridge/canbridge_options.h"
#include "procs/canbridge/command_limiter.h"
#include "procs/canbridge/drive_link.h"
#include "procs/canbridge/frame_counters.h"
#include "procs/canbridge/latency_stats.h"
#include "procs/canbridge/status_key.h"
#include "topay/base_velocity_t.hpp"
#include "topay/control_command_t.hpp"
#include "topay/drive_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay/joint_state_t.hpp"

namespace topay::procs {
class ProcessLoop;
}

namespace topay::canbridge {

/// The messages one cycle produced (each only when there is something new).
struct CanbridgeOutputs {
  std::optional<base_velocity_t> base_velocity;
  std::optional<joint_state_t> joint_state;
  std::optional<drive_status_t> status;
};

class CanbridgeNode {
 public:
  /// `bus` must outlive the node. `listen_only` (replay): decode and publish, never send.
  /// The joints are the model's (names, limits); options.drives.node_ids must have one per
  /// joint. Throws std::invalid_argument for inconsistent options.
  CanbridgeNode(const CanbridgeOptions& options, const RobotModel& model, can::CanBus* bus,
                bool listen_only = false);

  /// A CONTROL_COMMAND received at now_s: checked (rejected and counted when malformed), kept as
  /// the latest command, and while running its clamped frames are sent at once.
  void OnCommand(const control_command_t& msg, double now_s);
  /// A DRIVE_COMMAND (FAULT_RESET) received at now_s. Returns "" when acted on, else why not.
  std::string OnDriveCommand(const drive_command_t& msg, double now_s);
  /// One CAN cycle at now_s (monotonic) / now_utime (message stamps).
  const CanbridgeOutputs& Cycle(double now_s, std::int64_t now_utime);
  /// How late the cycle started against its schedule (the loop measures it).
  void RecordCycleLateness(double seconds) { jitter_.Add(seconds < 0 ? -seconds : seconds); }

  BridgeState state() const { return state_; }
  const std::string& stop_reason() const { return stop_reason_; }
  const BaseLink& base() const { return base_; }
  const std::vector<DriveLink>& drives() const { return drives_; }
  const FrameCounters& frame_counters() const { return counters_; }
  const CommandLimiter& limiter() const { return limiter_; }
  const LatencyStats& command_latency() const { return latency_; }
  const LatencyStats& cycle_jitter() const { return jitter_; }
  std::int64_t commands_received() const { return commands_received_; }
  std::int64_t commands_rejected() const { return commands_rejected_; }
  std::int64_t tx_refused() const { return tx_refused_; }
  std::int64_t cycles() const { return cycles_; }
  /// The status message now (what DRIVE_STATUS would carry).
  drive_status_t StatusMessage(double now_s, std::int64_t now_utime);
  /// heartbeat_t::OK running (or replaying), WARN starting/enabling/stopped/recovering, ERROR fault.
  std::int8_t Health() const;
  std::string StatusLine(double now_s);
  /// The exit report: state, counts, frames, latency and jitter (median, p99, max), bus load.
  std::string Report(double now_s);

 private:
  void ReadFrames(double now_s);
  void Dispatch(const can::CanFrame& frame, double now_s);
  void ServiceBus(double now_s);
  void UpdateState(double now_s);
  void SendCycleFrames(double now_s);
  bool SendFrame(const can::CanFrame& frame, double now_s);
  void Enter(BridgeState state, double now_s, std::string reason);
  void BeginRecovery(double now_s);
  // Arms every device's fault reset and recovers (FAULT_RESET, or the automatic one).
  void ResetFaults(double now_s);
  // options.auto_reset_communication_faults: in FAULT, reads the faulted drives' codes and
  // resets them itself when all are communication errors (0x81xx) or RPDO timeouts (0x8250).
  void MaybeResetCommunicationFault(double now_s);
  void MarkRestarts(double now_s);
  std::string FaultCause() const;
  std::string TransientCause(double now_s) const;
  std::string NotReadyText() const;
  bool CommandStale(double now_s) const;
  bool CommandAllowsRecovery(double now_s) const;
  bool AllDrivesOperational() const;
  void FillOutputs(double now_s, std::int64_t now_utime);
  // The key of the status now, into *key (its storage reused).
  void FillStatusKey(StatusKey* key) const;

  CanbridgeOptions options_;
  can::CanBus* bus_;
  bool listen_only_;
  BaseLink base_;
  std::vector<DriveLink> drives_;
  std::vector<bool> restart_;
  CommandLimiter limiter_;
  FrameCounters counters_;
  BusLoadMeter load_;
  LatencyStats latency_;
  LatencyStats jitter_;
  CanbridgeOutputs outputs_;

  BridgeState state_ = BridgeState::kStarting;
  std::string stop_reason_ = "starting";
  double state_since_s_ = 0.0;
  std::optional<double> cause_clear_since_s_;
  std::optional<double> fault_reset_s_;
  std::deque<double> auto_resets_s_;  // times of the automatic resets within the last 60 s
  bool auto_reset_limit_logged_ = false;
  bool bus_down_ = false;
  double last_reopen_s_ = -1e9;
  double last_host_heartbeat_s_ = -1e9;
  double last_status_s_ = -1e9;
  std::vector<can::CanFrame> cycle_frames_;  // SendCycleFrames' frames (kept for its capacity)
  StatusKey status_key_;       // this cycle's (scratch, swapped with the last published one)
  StatusKey last_status_key_;  // of the last DRIVE_STATUS published
  bool started_ = false;

  DeviceCommand latest_command_;
  std::optional<double> last_command_s_;
  std::int64_t commands_received_ = 0;
  std::int64_t commands_rejected_ = 0;
  std::string last_command_error_;
  std::int64_t tx_refused_ = 0;
  std::int64_t cycles_ = 0;
};

/// Subscribes `node` to CONTROL_COMMAND and DRIVE_COMMAND on *loop and adds the cycle (every
/// period_s, on a fixed schedule; its lateness is the jitter) that publishes BASE_VELOCITY,
/// JOINT_STATE and DRIVE_STATUS and sets the heartbeat. `finished` (may be empty) is asked after
/// each cycle; true stops the loop (the end of a replay). Call before Run.
void ConnectCanbridgeNode(procs::ProcessLoop* loop, CanbridgeNode* node, double period_s,
                          std::function<bool()> finished = {});

}  // namespace topay::canbridge
