#pragma once
// The fault (emergency) frame (base -> host, id 0x080 + node, 8 bytes, sent once when a fault
// is raised, before the next status frame; the status frame keeps reporting it):
//   byte 0    fault code of the fault just raised (BaseFault 1..10)
//   byte 1    the mode the controller is in after it (normally 3, fault)
//   bytes 2-3 fault word uint16 LE: all active faults (must include the raised one's bit)
//   bytes 4-5 reserved, 0
//   byte 6    rolling counter (+1 per fault frame)
//   byte 7    checksum

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/base/base_mode.h"
#include "drivers/base/fault_codes.h"
#include "drivers/can/can_frame.h"

namespace topay::base {

struct FaultReport {
  BaseFault fault = BaseFault::kOverCurrent;  ///< The fault just raised.
  BaseMode mode = BaseMode::kFault;           ///< The mode after it.
  std::uint16_t fault_bits = 0;               ///< All active faults, including `fault`'s bit.
  std::uint8_t counter = 0;
};

/// The frame for `report`; nullopt with *error for a bad node id, an unknown fault code or
/// mode, undefined fault bits, or fault bits without the raised fault's bit.
std::optional<can::CanFrame> EncodeFault(const FaultReport& report, int node_id,
                                         std::string* error);

/// The report in `frame`, or nullopt with *error naming the frame and the problem.
std::optional<FaultReport> DecodeFault(const can::CanFrame& frame, int node_id,
                                       std::string* error);

}  // namespace topay::base
