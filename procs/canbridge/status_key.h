#pragma once
// What makes the bridge publish DRIVE_STATUS at once rather than at its period
// (CanbridgeOptions::status_period_s): the values an operator must see change the cycle they
// change (docs/canbridge.md, "Channels and messages": DRIVE_STATUS). The node compares this key
// every cycle (200 Hz), so it is plain data compared field by field; the node fills a kept key in
// place (CanbridgeNode::FillStatusKey), which allocates nothing once its storage has grown.

#include <cstdint>
#include <string>
#include <vector>

#include "drivers/can/can_bus.h"
#include "procs/canbridge/bridge_state.h"

namespace topay::canbridge {

/// One drive's part of the key.
struct DriveStatusKey {
  int cia402_state = -1;        ///< cia402::DriveState, -1 before its first statusword.
  std::uint16_t emcy_code = 0;  ///< Its last emergency error code (0: none or reset).
  int phase = -1;               ///< DrivePhase.
  bool operator==(const DriveStatusKey&) const = default;
};

struct StatusKey {
  BridgeState state = BridgeState::kStarting;
  std::string stop_reason;
  can::CanBusState bus_state = can::CanBusState::kErrorActive;
  int base_mode = -1;  ///< base::BaseMode, -1 before the base's first status.
  std::uint16_t base_fault_bits = 0;
  std::vector<DriveStatusKey> drives;  ///< In the node's drive order.
  bool operator==(const StatusKey&) const = default;
};

}  // namespace topay::canbridge
