#pragma once
// The odometry feedback (base -> host, id 0x300 + node, 8 bytes, every 10 ms (100 Hz)): the
// wheel encoders' accumulated tick counts, which the host integrates into a pose (the frame
// carries no pose: a pose needs more than 8 bytes and drifts the same way).
//   bytes 0-2 left wheel ticks   uint24 LE, modulo 2^24 (wraps; forward counts up)
//   bytes 3-5 right wheel ticks  uint24 LE, same
//   byte 6    rolling counter
//   byte 7    checksum
// The host takes differences between consecutive frames with WheelTickDelta (a wheel turns
// far less than 2^23 ticks in 10 ms) and converts them with DriveGeometry::ticks_per_rev.

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::base {

inline constexpr std::uint32_t kTickCountModulus = 1u << 24;

struct OdometryFeedback {
  std::uint32_t left_ticks = 0;   ///< 0..2^24-1 (the encoder sends its count modulo 2^24).
  std::uint32_t right_ticks = 0;
  std::uint8_t counter = 0;
};

/// The frame for `odometry`; tick counts are taken modulo 2^24 (the wrap is the protocol's, not
/// an error). nullopt with *error only for a bad node id.
std::optional<can::CanFrame> EncodeOdometry(const OdometryFeedback& odometry, int node_id,
                                            std::string* error);

/// The tick counts in `frame`, or nullopt with *error naming the frame and the problem. When
/// `last_counter` is given, a repeated counter is refused as stale (the host would otherwise
/// count a zero motion twice, harmless, but it means the base's feedback stopped).
std::optional<OdometryFeedback> DecodeOdometry(const can::CanFrame& frame, int node_id,
                                               std::optional<std::uint8_t> last_counter,
                                               std::string* error);

/// The signed tick difference current - last across the 2^24 wrap, in [-2^23, 2^23).
std::int32_t WheelTickDelta(std::uint32_t last_ticks, std::uint32_t current_ticks);

}  // namespace topay::base
