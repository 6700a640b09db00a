#pragma once
// The datagram of the user-space CAN bus (udp_can_bus.h): one classic CAN frame per UDP
// datagram, with the sender's id and sequence number.
//
// Layout: 32 bytes, multi-byte fields little-endian whatever the host's byte order.
//   offset size field
//    0      4   magic "TCAN" (0x54 0x43 0x41 0x4E)
//    4      1   version, 1
//    5      3   reserved, 0 (ignored when read)
//    8      4   sender id (u32): the sending node, so that it can drop its own frames
//   12      4   sequence (u32): per sender, +1 per frame (wraps), to detect lost frames
//   16     16   the frame, laid out as the kernel's `struct can_frame`:
//   16      4     can_id (u32): id | CAN_EFF_FLAG | CAN_RTR_FLAG | CAN_ERR_FLAG (linux/can.h)
//   20      1     len: data length 0..8
//   21      3     __pad, __res0, len8_dlc: 0 (ignored when read)
//   24      8     data[8]: len bytes, the rest 0
// On a little-endian host bytes 16..31 are exactly the `struct can_frame` a CAN_RAW socket
// reads or writes.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::can {

inline constexpr std::size_t kUdpCanDatagramBytes = 32;
inline constexpr std::uint8_t kUdpCanDatagramVersion = 1;

/// One decoded datagram.
struct UdpCanDatagram {
  std::uint32_t sender_id = 0;
  std::uint32_t sequence = 0;
  CanFrame frame;
};

/// The 32 bytes of `datagram`. Throws std::invalid_argument when the frame is invalid.
std::array<std::uint8_t, kUdpCanDatagramBytes> EncodeUdpCanDatagram(const UdpCanDatagram& datagram);

/// Decodes `size` bytes; nullopt with *error (when not null) naming what is wrong: the size,
/// the magic, the version or the frame (e.g. "frame: DLC 9 is above 8").
std::optional<UdpCanDatagram> DecodeUdpCanDatagram(const std::uint8_t* bytes, std::size_t size,
                                                   std::string* error);

}  // namespace topay::can
