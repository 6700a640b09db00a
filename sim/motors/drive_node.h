#pragma once
// One arm joint's CiA 402 drive as a CANopen node (docs/cia402.md, docs/motorsim.md): NMT
// state (boot-up message, pre-operational, operational, stopped, resets), an SDO server over
// DriveObjectDictionary (the host's start-up writes answered or aborted), the producer
// heartbeat at 0x1017 and the host's heartbeat consumed per 0x1016, RPDO1 (controlword +
// target velocity) acted on at SYNC and TPDO1 (statusword, position) + TPDO2 (velocity) sent on
// every SYNC, EMCY on a fault and on its reset, and the power state machine
// (drivers/arm/cia402_drive_model.h) with motion: only Operation enabled follows the target
// velocity; quick stop and the fault reaction ramp it to zero at the quick-stop deceleration,
// every other state commands zero. Pure: times are passed in, the joint's measured position and
// velocity come from the plant.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/cia402_drive_model.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/can/can_frame.h"
#include "sim/motors/drive_object_dictionary.h"

namespace topay::sim::motors {

struct DriveNodeOptions {
  int node_id = 1;                       ///< CANopen node id 1..127 (joint k: node k by default)
  cia402::JointUnits units;              ///< PDO units and bounds (drivers/arm/arm_pdo.h)
  cia402::DriveModelOptions model;       ///< quick stop option (default: codes 1..4, -> Switch on disabled)
  int producer_heartbeat_ms = 100;       ///< power-on value of 0x1017 (the host's start-up writes set it too)
  double max_velocity_radps = 2.35;      ///< the drive's velocity limit (|target| clamped), rad/s
  double quick_stop_decel_radps2 = 6.28; ///< quick stop and fault reaction ramp, rad/s^2
  double standstill_radps = 0.01;        ///< below this the joint counts as stopped, rad/s
  double fault_reaction_timeout_s = 0.5; ///< the fault reaction ends after this at the latest, s
  std::uint16_t fault_emcy_code = 0x5000;  ///< EMCY code of an injected fault (device hardware)
};

/// Empty when the options are valid, else what is wrong.
std::string CheckDriveNodeOptions(const DriveNodeOptions& options);

struct DriveNodeCounts {
  std::int64_t syncs = 0;            ///< SYNCs acted on (operational)
  std::int64_t rpdos = 0;            ///< RPDO1s accepted
  std::int64_t sdo_writes = 0;       ///< downloads confirmed
  std::int64_t sdo_reads = 0;
  std::int64_t sdo_aborts = 0;       ///< requests answered with an abort
  std::int64_t nmt_commands = 0;
  std::int64_t refused_controlwords = 0;  ///< controlwords the state machine refused
  std::int64_t malformed = 0;        ///< frames to this node a decoder refused
  std::int64_t emcy = 0;             ///< EMCY frames sent (faults and resets)
  std::int64_t faults = 0;           ///< faults entered (injected or host heartbeat lost)
  std::int64_t heartbeats = 0;       ///< heartbeats sent (boot-up included)
  std::int64_t host_heartbeat_lost = 0;
  std::int64_t rpdo_timeouts = 0;    ///< RPDO1 deadlines missed (EMCY 0x8250 and a fault)
  std::int64_t frames_sent = 0;
};

/// The joint as the drive's encoder sees it.
struct JointFeedback {
  double position_rad = 0.0;
  double velocity_radps = 0.0;
};

class DriveNode {
 public:
  /// Powers on at start_time_s: the boot-up message goes out at the first Step. `options` must
  /// pass CheckDriveNodeOptions (else std::invalid_argument).
  DriveNode(const DriveNodeOptions& options, double start_time_s);

  /// The joint's latest measured state (used by the TPDOs); none yet: no TPDOs.
  void SetFeedback(const JointFeedback& feedback) { feedback_ = feedback; }

  /// A frame from the bus at time_s; replies (SDO, TPDOs on SYNC, EMCY) are appended to *out.
  /// True when it was for this node (or a broadcast it acted on).
  bool OnFrame(const can::CanFrame& frame, double time_s, std::vector<can::CanFrame>* out);

  /// Advances to time_s: the boot-up message, the heartbeat (unless suppressed), the host's
  /// heartbeat check, RPDO1's deadline (0x1400:05), the quick-stop and fault-reaction ramps.
  void Step(double time_s, bool heartbeat_suppressed, std::vector<can::CanFrame>* out);

  /// A drive fault now (fault injection): EMCY `emcy_code` (0: the options' code) and the fault
  /// reaction (transition 13), then Fault (14) once stopped.
  void InjectFault(std::uint16_t emcy_code, double time_s, std::vector<can::CanFrame>* out);

  /// The joint rate the drive drives now (the plant's joint command), rad/s.
  double velocity_command_radps() const { return output_radps_; }
  cia402::DriveState state() const { return model_.state(); }
  canopen::NmtState nmt_state() const { return nmt_; }
  const DriveObjectDictionary& dictionary() const { return dictionary_; }
  const DriveNodeCounts& counts() const { return counts_; }
  const std::string& last_error() const { return last_error_; }
  int node_id() const { return options_.node_id; }

 private:
  void PowerOn(bool reset_application);
  void OnNmt(const can::CanFrame& frame);
  void OnSync(std::vector<can::CanFrame>* out);
  bool DueOnThisSync(std::uint16_t tpdo_comm_index) const;
  void OnRpdo1(const can::CanFrame& frame, double time_s, std::vector<can::CanFrame>* out);
  void OnSdo(const can::CanFrame& frame, std::vector<can::CanFrame>* out);
  void OnHostHeartbeat(const can::CanFrame& frame, double time_s);
  void CheckRpdoDeadline(double time_s, std::vector<can::CanFrame>* out);
  void ApplyControlword(std::uint16_t controlword, std::vector<can::CanFrame>* out);
  // EMCY, 0x1001/0x603F and the fault reaction (transition 13), its ramp timed from time_s.
  void EnterFault(std::uint16_t emcy_code, std::uint8_t error_register, double time_s, std::vector<can::CanFrame>* out);
  void SendEmcy(std::uint16_t code, std::uint8_t error_register, std::vector<can::CanFrame>* out);
  void UpdateOutput(double dt_s);
  void UpdateStatusObjects();
  void Emit(const std::optional<can::CanFrame>& frame, const std::string& error, std::vector<can::CanFrame>* out);

  DriveNodeOptions options_;
  DriveObjectDictionary dictionary_;
  cia402::DriveModel model_;
  canopen::NmtState nmt_ = canopen::NmtState::kBootUp;
  bool boot_up_due_ = true;
  canopen::HeartbeatProducer producer_;
  int producer_ms_ = -1;            // the 0x1017 the producer was made with
  canopen::HeartbeatConsumer consumer_{0.0};
  int consumer_ms_ = -1;            // the 0x1016 time the consumer was made with
  bool host_lost_ = false;
  std::optional<cia402::Rpdo1> pending_rpdo_;  // acted on at the next SYNC
  std::optional<double> last_rpdo_s_;  // the deadline's start: the last RPDO1 while operational
  double target_radps_ = 0.0;
  double output_radps_ = 0.0;
  std::optional<JointFeedback> feedback_;
  double last_step_s_;
  double fault_reaction_since_s_ = 0.0;
  DriveNodeCounts counts_;
  std::string last_error_;
};

}  // namespace topay::sim::motors
