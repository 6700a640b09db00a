#pragma once
// The host side of one arm joint's CiA 402 drive over CANopen (docs/cia402.md): its start-up
// (NMT reset communication, boot-up, enter pre-operational, the start-up SDO writes one at a
// time with timeouts and retries, NMT start), the controlword each cycle (the enable sequence
// of cia402_host.h, quick stop, fault reset only when armed), the RPDO1, and the feedback:
// TPDO1/TPDO2, EMCY, heartbeat (consumer) and SDO replies.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_state.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/startup_sdo.h"
#include "drivers/can/can_frame.h"
#include "procs/canbridge/canbridge_options.h"
#include "procs/canbridge/frame_result.h"

namespace topay::canbridge {

/// Where a drive's start-up is.
enum class DrivePhase {
  kIdle,            ///< Not started yet.
  kWaitingBootUp,   ///< NMT reset communication sent; waiting for the boot-up message.
  kConfiguring,     ///< Start-up SDO writes under way.
  kOperational,     ///< NMT start sent: PDOs flow.
  kFailed,          ///< A write was aborted or never confirmed; tried again after retry_after_s.
};
const char* ToString(DrivePhase phase);

/// What the bridge wants a drive to do this cycle.
enum class DriveIntent {
  kEnable,    ///< Towards Operation enabled (fault reset only when armed).
  kQuickStop, ///< Quick stop (0x0002) in Operation enabled / Quick stop active, else 0x0000.
};

class DriveLink {
 public:
  /// `writes` are StartupSdoWrites(node_id, ...). Throws std::invalid_argument for a bad node id.
  DriveLink(int node_id, std::string joint_name, const DriveLinkOptions& options,
            std::vector<cia402::SdoWrite> writes);

  FrameResult Handle(const can::CanFrame& frame, double now_s, std::string* error);
  /// The same for a frame already classified as `cob` (canopen::ClassifyCobId of its id): the
  /// node classifies each frame once and hands it to the drive of its node id.
  FrameResult Handle(const can::CanFrame& frame, const canopen::CobIdClass& cob, double now_s, std::string* error);

  /// Starts (again) the start-up from NMT reset communication.
  void BeginStartup(double now_s);
  /// The start-up frames due at now_s (NMT, one SDO request); when operational, only the
  /// error-code read's request (RequestErrorCode).
  void StartupStep(double now_s, std::vector<can::CanFrame>* out);

  /// The RPDO1 of this cycle for `intent` with target velocity `qdot_radps` (0 unless enabled).
  can::CanFrame Rpdo(DriveIntent intent, double qdot_radps);
  /// Allows fault reset edges while the drive reports Fault (DRIVE_COMMAND FAULT_RESET).
  void ArmFaultReset() {
    fault_reset_armed_ = true;
    emcy_active_ = false;
    error_code_.reset();
    error_code_read_ = ErrorCodeRead{};
  }
  /// Reads the drive's error code (0x603F:00) by SDO upload while it is operational: a fault
  /// whose EMCY was lost (sent while the bus was off) is named by it. The request goes out with
  /// the next StartupStep, again after sdo_timeout_s, at most sdo_attempts times; a call while
  /// one is under way, answered or given up (until the next fault reset) does nothing.
  void RequestErrorCode();
  /// The code the current fault is known by: the active EMCY's, else the 0x603F read since the
  /// last fault reset (nullopt: not known yet).
  std::optional<std::uint16_t> FaultCode() const;
  /// The 0x603F read gave up (no answer, or an abort).
  bool error_code_unavailable() const { return error_code_read_.gave_up; }

  int node_id() const { return node_id_; }
  const std::string& joint_name() const { return joint_name_; }
  DrivePhase phase() const { return phase_; }
  const std::string& failure() const { return failure_; }
  std::optional<cia402::DriveState> state() const { return state_; }
  std::optional<std::uint16_t> statusword() const { return statusword_; }
  bool enabled() const { return state_ == cia402::DriveState::kOperationEnabled; }
  /// Fault or fault reaction reported, or an EMCY with a non-zero code not yet reset.
  bool faulted() const;
  std::uint16_t last_emcy_code() const { return last_emcy_code_; }
  std::optional<canopen::NmtState> nmt_state() const { return heartbeat_.last_state(); }
  /// Seconds since the last heartbeat (or boot-up), -1 before the first.
  double heartbeat_age_s(double now_s) const { return last_heartbeat_s_ ? now_s - *last_heartbeat_s_ : -1.0; }
  /// Operational and silent: no heartbeat for heartbeat_timeout_s (counted from NMT start at the
  /// latest), or no TPDO1 for pdo_timeout_s. Empty when not lost, else why.
  std::string LostReason(double now_s) const;
  /// A boot-up message came while operational (the drive restarted): it must be started again.
  bool rebooted() const { return rebooted_; }
  double position_rad() const { return position_rad_; }
  double velocity_rad_per_s() const { return velocity_rad_per_s_; }
  /// Whether new position/velocity feedback came since the last call.
  bool TakeNewFeedback();
  /// "q3 (node 3)".
  std::string Label() const;

 private:
  FrameResult HandleSdoReply(const can::CanFrame& frame, double now_s, std::string* error);
  void Fail(std::string why, double now_s);
  void SendWrite(double now_s, std::vector<can::CanFrame>* out);
  void ErrorCodeStep(double now_s, std::vector<can::CanFrame>* out);
  void HandleErrorCodeReply(const canopen::SdoServerReply& reply);

  struct ErrorCodeRead {
    bool wanted = false;
    bool gave_up = false;
    int requests = 0;
    double sent_s = 0.0;
  };

  int node_id_;
  std::string joint_name_;
  DriveLinkOptions options_;
  std::vector<cia402::SdoWrite> writes_;
  DrivePhase phase_ = DrivePhase::kIdle;
  std::string failure_;
  double phase_since_s_ = 0.0;
  std::size_t next_write_ = 0;
  int attempts_ = 0;
  double write_sent_s_ = 0.0;
  bool write_pending_ = false;
  bool boot_seen_ = false;
  canopen::HeartbeatConsumer heartbeat_;
  std::optional<double> last_heartbeat_s_;
  std::optional<double> last_tpdo1_s_;
  double operational_since_s_ = 0.0;
  bool rebooted_ = false;
  std::optional<cia402::DriveState> state_;
  std::optional<std::uint16_t> statusword_;
  std::uint16_t previous_controlword_ = 0;
  bool fault_reset_armed_ = false;
  std::uint16_t last_emcy_code_ = 0;
  bool emcy_active_ = false;
  std::optional<std::uint16_t> error_code_;  // 0x603F, read since the last fault reset
  ErrorCodeRead error_code_read_;
  double position_rad_ = 0.0;
  double velocity_rad_per_s_ = 0.0;
  bool new_feedback_ = false;
};

}  // namespace topay::canbridge
