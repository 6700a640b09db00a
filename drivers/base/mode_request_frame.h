#pragma once
// The mode request (host -> base, id 0x100 + node, 2 bytes, on demand; the host repeats it
// every 100 ms until the status frame shows the mode):
//   byte 0  request code (ModeRequest: 0 standby, 1 CAN command, 2 quick stop, 3 fault reset)
//   byte 1  the code's complement (0xFF - code): a corrupted request is never acted on

#include <optional>
#include <string>

#include "drivers/base/base_mode.h"
#include "drivers/can/can_frame.h"

namespace topay::base {

/// The frame for `request`; nullopt with *error for a bad node id or an unknown request code.
std::optional<can::CanFrame> EncodeModeRequest(ModeRequest request, int node_id,
                                               std::string* error);

/// The request in `frame`, or nullopt with *error naming the frame and the problem (wrong
/// kind/id/DLC, complement mismatch, unknown request code).
std::optional<ModeRequest> DecodeModeRequest(const can::CanFrame& frame, int node_id,
                                             std::string* error);

}  // namespace topay::base
