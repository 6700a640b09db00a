#pragma once
// The bridge's states (drive_status_t's constants, docs/canbridge.md "States and recovery").

#include <cstdint>

namespace topay::canbridge {

enum class BridgeState : std::int8_t {
  kStarting = 0,    ///< Configuring the devices: base status, NMT, start-up SDOs.
  kEnabling = 1,    ///< CiA 402 enable sequence and the base's CAN command mode.
  kRunning = 2,     ///< Commands go to the bus, clamped.
  kStopped = 3,     ///< Zero + quick stop: a transient cause (stale command, lost device, bus).
  kFault = 4,       ///< Zero + quick stop: a device fault; waits for DRIVE_COMMAND FAULT_RESET.
  kRecovering = 5,  ///< Cause gone: re-configuring / re-enabling before running again.
  kReplay = 6,      ///< --replay: decoding a recorded log, sending nothing.
};

/// "starting", "enabling", "running", "stopped", "fault", "recovering", "replay".
const char* ToString(BridgeState state);

}  // namespace topay::canbridge
