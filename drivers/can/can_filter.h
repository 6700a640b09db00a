#pragma once
// Receive filters with SocketCAN's semantics (CAN_RAW_FILTER, `struct can_filter`), so that
// the SocketCAN backend hands them to the kernel and the user-space backend applies the very
// same rule itself.

#include <cstdint>
#include <string>
#include <vector>

#include "drivers/can/can_frame.h"

namespace topay::can {

/// One id/mask filter in the kernel's form: a frame passes when
///   (frame_can_id & can_mask) == (can_id & can_mask)
/// where frame_can_id is the frame's id with its CAN_EFF_FLAG and CAN_RTR_FLAG bits (as in
/// `struct can_frame`), and `can_id` may carry CAN_INV_FILTER to invert the test. Use the
/// helpers below rather than raw bits where possible.
struct CanFilter {
  std::uint32_t can_id = 0;    ///< Id to compare, with EFF/RTR flag bits, maybe CAN_INV_FILTER.
  std::uint32_t can_mask = 0;  ///< Bits that must match; 0 lets every frame pass.

  /// Standard (11-bit) data and remote frames whose id matches `id` on the bits of `mask`
  /// (default: exactly `id`); extended frames never pass.
  static CanFilter Standard(std::uint32_t id, std::uint32_t mask = CAN_SFF_MASK);
  /// Extended (29-bit) frames whose id matches `id` on the bits of `mask` (default: exactly).
  static CanFilter Extended(std::uint32_t id, std::uint32_t mask = CAN_EFF_MASK);
};

/// Whether `frame` passes `filter`. Error frames are not subject to id filters (SocketCAN
/// selects them with CAN_RAW_ERR_FILTER instead); this returns true for them.
bool Matches(const CanFilter& filter, const CanFrame& frame);

/// Whether `frame` passes a filter list: an empty list lets everything pass (the default of a
/// fresh CAN_RAW socket), otherwise at least one filter must match.
bool PassesFilters(const std::vector<CanFilter>& filters, const CanFrame& frame);

/// Readable form, e.g. "123:7FF" (hex, like candump's filter argument; '~' when inverted).
std::string ToString(const CanFilter& filter);

}  // namespace topay::can
