#pragma once
// The status frame (base -> host, id 0x180 + node, 8 bytes, every 50 ms (20 Hz) and at once on
// a mode change):
//   byte 0    mode (BaseMode 0..3)
//   byte 1    error code: the most recent active fault's code (fault_codes.h), 0 when none
//   bytes 2-3 fault word uint16 LE: one bit per active fault (only bits 0..9 defined)
//   bytes 4-5 battery voltage uint16 LE, 10 mV units, 0..10000 (0..100 V)
//   byte 6    rolling counter
//   byte 7    checksum

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/base/base_mode.h"
#include "drivers/can/can_frame.h"

namespace topay::base {

inline constexpr std::int32_t kMaxBatteryVoltageRaw = 10000;  ///< 10 mV units: 100 V.

struct BaseStatus {
  BaseMode mode = BaseMode::kStandby;
  std::uint8_t error_code = 0;      ///< 0 or a BaseFault code (1..10).
  std::uint16_t fault_bits = 0;     ///< Active faults (FaultBit), only kDefinedFaultBits.
  double battery_voltage_v = 0.0;   ///< Rounded to 10 mV.
  std::uint8_t counter = 0;
};

/// The frame for `status`; nullopt with *error for a bad node id, mode, error code or fault
/// bits, or a battery voltage that is not finite or outside 0..100 V (rejected, not saturated).
std::optional<can::CanFrame> EncodeStatus(const BaseStatus& status, int node_id,
                                          std::string* error);

/// The status in `frame`, or nullopt with *error naming the frame and the problem.
std::optional<BaseStatus> DecodeStatus(const can::CanFrame& frame, int node_id,
                                       std::string* error);

}  // namespace topay::base
