#pragma once
// topay-canbridge's options (config/canbridge/canbridge.yaml, docs/canbridge.md): the bus, the
// cycle, the safety timeouts and recovery, the base controller's node and geometry, the arm
// drives' node ids and start-up. The robot's limits come from the robot description.

#include <string>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/startup_sdo.h"
#include "drivers/base/diff_drive_kinematics.h"

namespace topay::canbridge {

/// The differential-drive base's controller (docs/base_protocol.md).
struct BaseLinkOptions {
  /// Node id of the base controller, 1..127. Default 16: the base protocol's ids (0x080 + node
  /// .. 0x300 + node) share the CANopen function bases, so the base must not use a drive's node
  /// id (1..7) nor the host's (127); 16 (0x10) is clear of both.
  int node_id = 16;
  /// Repeat an unacknowledged mode request every this many seconds. Default 0.1 s (the protocol).
  double mode_request_repeat_s = 0.1;
  /// Status silence after which the base counts as lost [s]. Default 0.25 s (5 status periods).
  double status_timeout_s = 0.25;
  /// Wheel radius, track width, encoder ticks (docs/base_protocol.md defaults).
  base::DriveGeometry geometry;
};

/// The arm's CiA 402 drives (docs/cia402.md).
struct DriveLinkOptions {
  /// CANopen node id of each joint's drive, q1..qN order. Default 1..7.
  std::vector<int> node_ids = {1, 2, 3, 4, 5, 6, 7};
  /// A drive whose heartbeats stop for this long is lost [s]. Default 0.5 s (5 of its 100 ms
  /// periods: with 10 % frame loss three in a row go missing too often; a dead drive is caught
  /// sooner by pdo_timeout_s).
  double heartbeat_timeout_s = 0.5;
  /// An operational drive whose TPDO1 stops for this long is lost [s]; 0 disables. Default
  /// 0.1 s (20 SYNC periods).
  double pdo_timeout_s = 0.1;
  /// Wait this long for an SDO confirmation before sending the request again [s]. Default 0.1 s.
  double sdo_timeout_s = 0.1;
  /// Requests of one SDO write before the start-up counts as failed. Default 3.
  int sdo_attempts = 3;
  /// Wait this long for the boot-up message after NMT reset communication before going on
  /// without it (enter pre-operational) [s]. Default 0.5 s.
  double boot_timeout_s = 0.5;
  /// A failed start-up (SDO abort or no answer) is tried again after this long [s]. Default 1 s.
  double retry_after_s = 1.0;
  /// The host's (bridge's) heartbeat period [s]. Default 0.05 s: six per the drives' 0.3 s
  /// consumer time, so 10 % frame loss does not fault them.
  double host_heartbeat_period_s = 0.05;
  /// The start-up SDO writes' options (heartbeat times, host node id 127, mode 9). Its
  /// sync_period_ms is set from the bridge's cycle, not read.
  cia402::StartupOptions startup;
  /// Units and bounds of the PDOs (docs/cia402.md).
  cia402::JointUnits units;
};

struct CanbridgeOptions {
  std::string source;      ///< The file these came from ("" = defaults).
  std::string robot_urdf;  ///< "" = the shipped robot (config/robot/topay_mm.urdf).
  std::string robot_yaml;  ///< "" = config/robot/topay_mm.yaml.
  /// The bus (--can overrides it). Default udp://239.255.1.1:9000 (the motor simulator's).
  std::string can_url = "udp://239.255.1.1:9000";
  /// The CAN cycle [s]: SYNC, RPDOs, base velocity command. Default 0.005 s (200 Hz).
  double cycle_period_s = 0.005;
  /// The bus bit rate for the load figure [bit/s]. Default 1e6 (1 Mbit/s, the robot's can0).
  double bit_rate_bps = 1e6;
  /// The stop frames are on the bus at the latest this long after the last valid
  /// CONTROL_COMMAND [s]. Default 0.1 s (stack design).
  double command_timeout_s = 0.1;
  /// |v| [m/s], |omega| [rad/s] and every |qdot| [rad/s] at or below this count as zero (the
  /// condition of every recovery). Default 1e-3.
  double zero_command_tolerance = 1e-3;
  /// A transient stop cause must be gone this long before recovery [s]. Default 0.5 s.
  double recovery_hold_s = 0.5;
  /// ENABLING / RECOVERING that does not reach RUNNING within this long stops [s]. Default 3 s.
  double enable_timeout_s = 3.0;
  /// A fault reset that leaves a fault after this long is a fault again [s]. Default 1 s.
  double fault_reset_timeout_s = 1.0;
  /// Reset, as an operator's FAULT_RESET would, a fault of the drives alone whose every code
  /// (the active EMCY's, else 0x603F read by SDO) is a CAN communication error (0x81xx: e.g. the
  /// drive lost the bridge's heartbeat while the bus was off, its EMCY lost with it) or an RPDO
  /// timeout (0x8250: the bridge's setpoints stopped for rpdo_deadline_ms): the cause
  /// is gone once the bridge hears the drives again. Only at a zero command. Any other code, an
  /// unreadable one or a base fault waits for the operator. Default true.
  bool auto_reset_communication_faults = true;
  /// At most this many automatic resets within 60 s; then the operator's. Default 3.
  int max_auto_resets_per_minute = 3;
  /// DRIVE_STATUS period [s] (also published at once on every change). Default 0.1 s (10 Hz).
  double status_period_s = 0.1;
  /// Reopen a bus whose interface went down every this many seconds. Default 0.1 s.
  double bus_reopen_period_s = 0.1;
  /// The interface name written in --record logs. Default "can0".
  std::string record_interface = "can0";
  BaseLinkOptions base;
  DriveLinkOptions drives;

  /// Throws std::invalid_argument naming the first bad field.
  void Check() const;
};

/// Loads options from YAML (every key optional; relative robot paths from the file's folder).
/// Throws ConfigError naming the file and the dotted key for an unreadable file, an unknown key
/// or a value out of range.
CanbridgeOptions LoadCanbridgeOptions(const std::string& path);

}  // namespace topay::canbridge
