#pragma once
// A classic CAN frame (CAN 2.0A/B, up to 8 data bytes) as a value type, its conversion to and
// from the kernel's `struct can_frame`, and its text form in can-utils' cansend/candump syntax.

#include <linux/can.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace topay::can {

/// One classic CAN frame. Plain data: fields are public, CheckCanFrame() says whether they form
/// a valid frame. The invariant kept by every function of this library: data bytes at and
/// beyond `dlc` are zero (and every byte of a remote frame is zero).
///
/// Kinds of frame:
///  - data frame: `id` is 11 bits (0..0x7FF) or, with `extended`, 29 bits (0..0x1FFFFFFF);
///    `dlc` data bytes (0..8);
///  - remote frame (`remote`, RTR): an id and a requested length `dlc`, no data;
///  - error frame (`error`): not sent on the wire but reported by the controller's driver;
///    `id` holds the CAN_ERR_* class bits of linux/can/error.h (29 bits) and `data` the details
///    (can_error.h decodes them). An error frame is never `remote`; `extended` is ignored.
struct CanFrame {
  static constexpr std::uint32_t kMaxStandardId = CAN_SFF_MASK;  ///< 0x7FF (11 bits).
  static constexpr std::uint32_t kMaxExtendedId = CAN_EFF_MASK;  ///< 0x1FFFFFFF (29 bits).
  static constexpr int kMaxDlc = CAN_MAX_DLEN;                   ///< 8 data bytes.

  std::uint32_t id = 0;       ///< Identifier without flag bits (or error class bits).
  bool extended = false;      ///< 29-bit identifier (EFF).
  bool remote = false;        ///< Remote transmission request (RTR).
  bool error = false;         ///< Error frame reported by the driver (CAN_ERR_FLAG).
  std::uint8_t dlc = 0;       ///< Data length code, 0..8 (the number of data bytes).
  std::array<std::uint8_t, 8> data{};  ///< Payload; bytes at and beyond dlc are zero.

  /// A data frame with an 11-bit id. Throws std::invalid_argument (naming the problem) when the
  /// id is above 0x7FF or there are more than 8 bytes.
  static CanFrame Standard(std::uint32_t id, std::initializer_list<std::uint8_t> bytes = {});
  /// A data frame with a 29-bit id. Throws std::invalid_argument like Standard().
  static CanFrame Extended(std::uint32_t id, std::initializer_list<std::uint8_t> bytes = {});
  /// A remote frame requesting `dlc` bytes. Throws std::invalid_argument like Standard().
  static CanFrame Remote(std::uint32_t id, int dlc = 0, bool extended = false);
};

/// Empty when `frame` is valid, else what is wrong, e.g. "DLC 9 is above 8" or
/// "standard id 0x800 is above 0x7FF (use an extended id)".
std::string CheckCanFrame(const CanFrame& frame);

/// Same kind, id, length and payload (bytes beyond dlc are not compared).
bool operator==(const CanFrame& a, const CanFrame& b);
inline bool operator!=(const CanFrame& a, const CanFrame& b) { return !(a == b); }

/// The kernel's form (flags in can_id, len = dlc, padding zero). Throws std::invalid_argument
/// with CheckCanFrame()'s message when `frame` is invalid.
struct can_frame ToLinuxFrame(const CanFrame& frame);

/// The value form of a kernel frame; nullopt with *error (when not null) naming what is wrong:
/// a length above 8, a standard id with bits above 0x7FF, RTR on an error frame.
std::optional<CanFrame> FromLinuxFrame(const struct can_frame& frame, std::string* error);

/// The frame in cansend/candump syntax (upper-case hex, as `candump -l` writes it):
///   standard data `123#DEADBEEF`, extended `12345678#00` (always 8 id digits), empty `123#`,
///   remote `123#R` (or `123#R3` when it requests 3 bytes), error frames with 8 digits
///   including the CAN_ERR_FLAG bit, e.g. `20000040#0000000000000000` (bus-off).
std::string ToString(const CanFrame& frame);

/// Parses cansend syntax: `<id>#<data>`, the id in 3 hex digits (standard) or 8 (extended,
/// or an error frame when its value has the CAN_ERR_FLAG bit 0x20000000), the data as up to 8
/// bytes of 2 hex digits, optionally separated by '.', or `R` with an optional length digit for
/// a remote frame. CAN FD (`##`) and lengths above 8 are rejected. Returns nullopt with *error
/// (when not null) naming the bad part, e.g. "'12#00': the id must have 3 hex digits
/// (standard) or 8 (extended), found 2".
std::optional<CanFrame> ParseCanFrame(std::string_view text, std::string* error);

}  // namespace topay::can
