#pragma once
// The byte-level rules every base protocol frame shares (docs/base_protocol.md, "Encoding"):
// little-endian integers, the rolling counter in byte 6 and the checksum in byte 7 of the
// 8-byte frames, fixed-point scaling with rounding, and the id/DLC check that starts every
// decoder. Helpers for the frame files; callers use the frames' Encode/Decode functions.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "drivers/base/protocol_ids.h"
#include "drivers/can/can_frame.h"

namespace topay::base {

inline constexpr int kCounterByte = 6;   ///< Rolling counter (0..255, +1 per frame, wraps).
inline constexpr int kChecksumByte = 7;  ///< Checksum over the id and bytes 0..6.

/// Little-endian stores and loads at `offset` of `frame.data`.
void PutUint16Le(can::CanFrame& frame, int offset, std::uint16_t value);
void PutInt16Le(can::CanFrame& frame, int offset, std::int16_t value);
/// The low 24 bits of `value`, little-endian (odometry tick counts wrap at 2^24).
void PutUint24Le(can::CanFrame& frame, int offset, std::uint32_t value);
std::uint16_t GetUint16Le(const can::CanFrame& frame, int offset);
std::int16_t GetInt16Le(const can::CanFrame& frame, int offset);
std::uint32_t GetUint24Le(const can::CanFrame& frame, int offset);

/// The checksum of an 8-byte frame: 0xFF minus the low byte of the sum of the id's two bytes
/// and data bytes 0..6 (a corrupted byte or a frame sent with another node's id fails it).
std::uint8_t ComputeChecksum(const can::CanFrame& frame);

/// An empty 8-byte (or 2-byte) standard frame of `kind` for a valid `node_id`.
can::CanFrame MakeEmptyFrame(BaseFrameKind kind, int node_id);

/// Writes `counter` into byte 6 and then the checksum into byte 7.
void SealFrame(can::CanFrame& frame, std::uint8_t counter);

/// The checks every decoder starts with: a valid node id, a standard data frame, the id of
/// `kind` for `node_id`, the exact DLC and (8-byte frames) the checksum. Empty when they pass,
/// else the error naming the frame, e.g. "velocity command (0x201): DLC 6, expected 8".
std::string CheckFrameShape(const can::CanFrame& frame, BaseFrameKind kind, int node_id);

/// "velocity command (0x201)": the prefix of every error about a frame.
std::string FrameLabel(BaseFrameKind kind, int node_id);

/// `value` (SI units) * `units_per_si` rounded to the nearest integer (halves away from zero),
/// or nullopt with *error naming `field` when `value` is not finite or the rounded result is
/// outside [min_raw, max_raw]. Encoders reject such values, they never saturate silently.
std::optional<std::int32_t> ScaleToRaw(double value, double units_per_si, std::int32_t min_raw,
                                       std::int32_t max_raw, std::string_view field,
                                       std::string* error);

/// Empty when `raw` is in [min_raw, max_raw], else "<field> <raw> is outside min..max".
std::string CheckRawRange(std::int32_t raw, std::int32_t min_raw, std::int32_t max_raw,
                          std::string_view field);

/// The stale-frame check of a rolling counter: empty when `current` differs from `last` (or
/// there is no last), else "<frame>: counter N repeated (stale frame)".
std::string CheckRollingCounter(std::string_view frame_name, std::optional<std::uint8_t> last,
                                std::uint8_t current);

/// How many frames were lost between `last` and `current` (0 when current == last + 1 mod 256;
/// 255 for a repeated counter, which CheckRollingCounter reports as stale).
int CounterGap(std::uint8_t last, std::uint8_t current);

/// Stores `message` in *error when `error` is not null.
void SetError(std::string* error, std::string message);

}  // namespace topay::base
