#pragma once
// The wheel speeds feedback (base -> host, id 0x280 + node, 8 bytes, every 10 ms (100 Hz)):
//   bytes 0-1 left wheel   int16 LE, 1 mrad/s (0.001 rad/s), -30000..30000 (+-30 rad/s)
//   bytes 2-3 right wheel  int16 LE, same
//   bytes 4-5 reserved, 0
//   byte 6    rolling counter
//   byte 7    checksum
// Positive wheel speeds drive the robot forward (on both sides).

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::base {

inline constexpr std::int32_t kMaxWheelSpeedRaw = 30000;  ///< mrad/s.

struct WheelSpeedsFeedback {
  double left_rad_per_s = 0.0;
  double right_rad_per_s = 0.0;
  std::uint8_t counter = 0;
};

/// The frame for `speeds` (rounded to the nearest mrad/s); nullopt with *error for a bad node
/// id or a speed that is not finite or outside +-30 rad/s (rejected, not saturated).
std::optional<can::CanFrame> EncodeWheelSpeeds(const WheelSpeedsFeedback& speeds, int node_id,
                                               std::string* error);

/// The speeds in `frame`, or nullopt with *error naming the frame and the problem.
std::optional<WheelSpeedsFeedback> DecodeWheelSpeeds(const can::CanFrame& frame, int node_id,
                                                     std::string* error);

}  // namespace topay::base
