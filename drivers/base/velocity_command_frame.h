#pragma once
// The velocity command (host -> base, id 0x200 + node, 8 bytes, at the control rate):
//   bytes 0-1 v      int16 LE, 1 mm/s     (0.001 m/s),   -3000..3000 (+-3 m/s)
//   bytes 2-3 omega  int16 LE, 1 mrad/s   (0.001 rad/s), -10000..10000 (+-10 rad/s)
//   bytes 4-5 reserved, 0
//   byte 6    rolling counter, +1 per command (a repeated counter marks a stale command)
//   byte 7    checksum (frame_bytes.h)

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::base {

inline constexpr std::int32_t kMaxLinearSpeedRaw = 3000;    ///< mm/s.
inline constexpr std::int32_t kMaxAngularSpeedRaw = 10000;  ///< mrad/s.

struct VelocityCommand {
  double v_m_per_s = 0.0;        ///< Forward speed of the axle midpoint.
  double omega_rad_per_s = 0.0;  ///< Yaw rate, counter-clockwise positive.
  std::uint8_t counter = 0;      ///< Rolling counter, +1 per command sent.
};

/// The frame for `command`; v and omega are rounded to the nearest mm/s and mrad/s. Rejects
/// (nullopt and *error naming the field) a bad node id and values that are not finite or round
/// outside the ranges above: the sender clamps to the robot's limits first, the encoder never
/// saturates.
std::optional<can::CanFrame> EncodeVelocityCommand(const VelocityCommand& command, int node_id,
                                                   std::string* error);

/// The command in `frame`, or nullopt with *error naming the frame and the problem: wrong
/// kind/id/DLC, bad checksum, reserved bytes not zero, v or omega out of range, or (when
/// `last_counter` is given) a counter equal to the last accepted one (stale).
std::optional<VelocityCommand> DecodeVelocityCommand(const can::CanFrame& frame, int node_id,
                                                     std::optional<std::uint8_t> last_counter,
                                                     std::string* error);

}  // namespace topay::base
