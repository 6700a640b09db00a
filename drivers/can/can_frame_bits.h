#pragma once
// The exact length on the wire of a classic CAN frame (ISO 11898-1), bit stuffing included, for
// bus load figures: the bits of the stuffed region (SOF .. CRC) are built, CRC-15 computed, the
// stuff bits counted, and the fixed-form tail added (CRC delimiter, ACK slot and delimiter, EOF,
// intermission).
#include <cstdint>
#include <span>
#include <vector>

#include "drivers/can/can_frame.h"

namespace topay::can {

/// Bits after the CRC that are never stuffed: CRC delimiter 1, ACK slot 1, ACK delimiter 1,
/// end of frame 7, intermission (interframe space) 3.
inline constexpr int kCanFrameTailBits = 13;

/// CRC-15/CAN (polynomial x^15 + x^14 + x^10 + x^8 + x^7 + x^4 + x^3 + 1, 0x4599, initial 0)
/// over `bits` (0 or 1 each, in transmission order).
std::uint16_t CanCrc15(std::span<const std::uint8_t> bits);

/// The unstuffed bits from SOF up to the end of the data field, in transmission order (0 =
/// dominant): standard: SOF, 11 id bits, RTR, IDE (0), r0 (0), 4 DLC bits, data; extended: SOF,
/// 11 base id bits, SRR (1), IDE (1), 18 extension bits, RTR, r1 (0), r0 (0), DLC, data. RTR is
/// 1 for remote frames (which carry no data). Throws std::invalid_argument for an invalid or
/// error frame (error frames are reports of the controller, not frames on the wire).
std::vector<std::uint8_t> CanFrameHeaderAndDataBits(const CanFrame& frame);

/// The stuffed region before stuffing: CanFrameHeaderAndDataBits followed by the 15 CRC bits.
std::vector<std::uint8_t> CanFrameStuffedRegionBits(const CanFrame& frame);

/// Stuff bits a transmitter inserts into `bits`: after 5 equal bits in a row a complementary bit
/// is inserted, which counts towards the next run.
int CountStuffBits(std::span<const std::uint8_t> bits);

/// The frame's length on the wire in bits, including stuff bits, the tail and the 3-bit
/// intermission: e.g. 47 + stuff bits for a standard frame with no data, 111 + stuff bits with
/// 8 bytes. Error frames count 0 (they are not data on the bus). Throws std::invalid_argument
/// for an invalid frame. Allocation-free (the bridge measures every frame it sends and receives).
int CanFrameLengthBits(const CanFrame& frame);

}  // namespace topay::can
