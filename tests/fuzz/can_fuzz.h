#pragma once
// CAN frames in and out of a fuzzer's bytes, shared by the CAN fuzz targets (tests/fuzz/
// base_frames, canopen_frames, motorsim_frames, canbridge) and their seed writer
// (can_seeds_main.cc). One frame record is 14 bytes:
//   [flags][u32 id, little-endian][dlc][8 data bytes]
// flags bit 0 extended, bit 1 remote, bit 2 error frame: the CanFrame fields, in any combination,
// valid or not. Bits 3 ("seal") and 4 ("addressed") are the target's to read (e.g. recompute the
// checksum, build the id from a function and a node id), so that mutations get past the id and
// checksum checks to the fields behind them. The id and the DLC are taken as they are (ids above
// 29 bits, DLCs up to 255) and so are the data bytes beyond the DLC: a decoder must refuse what
// is invalid and never read past 8 bytes, whatever the fields hold.

#include <cstdint>
#include <cstring>
#include <vector>

#include "drivers/can/can_frame.h"
#include "tests/fuzz/fuzz_reader.h"

namespace topay::fuzz {

inline constexpr std::uint8_t kFrameExtended = 1u << 0;
inline constexpr std::uint8_t kFrameRemote = 1u << 1;
inline constexpr std::uint8_t kFrameError = 1u << 2;
inline constexpr std::uint8_t kFrameSeal = 1u << 3;
inline constexpr std::uint8_t kFrameAddressed = 1u << 4;

struct FrameRecord {
  can::CanFrame frame;
  std::uint8_t flags = 0;
  bool seal() const { return (flags & kFrameSeal) != 0; }
  bool addressed() const { return (flags & kFrameAddressed) != 0; }
};

inline FrameRecord NextFrameRecord(FuzzReader& in) {
  FrameRecord record;
  record.flags = in.Byte();
  record.frame.extended = (record.flags & kFrameExtended) != 0;
  record.frame.remote = (record.flags & kFrameRemote) != 0;
  record.frame.error = (record.flags & kFrameError) != 0;
  record.frame.id = in.U32();
  record.frame.dlc = in.Byte();
  for (std::uint8_t& byte : record.frame.data) byte = in.Byte();
  return record;
}

/// Builds inputs in the formats the readers above read (little-endian), for the seed writer.
class ByteWriter {
 public:
  ByteWriter& U8(std::uint8_t value) {
    bytes_.push_back(value);
    return *this;
  }
  ByteWriter& U16(std::uint16_t value) {
    return U8(static_cast<std::uint8_t>(value)).U8(static_cast<std::uint8_t>(value >> 8));
  }
  ByteWriter& U32(std::uint32_t value) {
    return U16(static_cast<std::uint16_t>(value)).U16(static_cast<std::uint16_t>(value >> 16));
  }
  ByteWriter& Double(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return U32(static_cast<std::uint32_t>(bits)).U32(static_cast<std::uint32_t>(bits >> 32));
  }
  ByteWriter& Bytes(const std::vector<std::uint8_t>& bytes) {
    bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
    return *this;
  }
  /// A frame record of `frame` with the target's `extra_flags` (kFrameSeal, kFrameAddressed).
  ByteWriter& Frame(const can::CanFrame& frame, std::uint8_t extra_flags = 0) {
    std::uint8_t flags = extra_flags;
    if (frame.extended) flags |= kFrameExtended;
    if (frame.remote) flags |= kFrameRemote;
    if (frame.error) flags |= kFrameError;
    U8(flags).U32(frame.id).U8(frame.dlc);
    for (const std::uint8_t byte : frame.data) U8(byte);
    return *this;
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace topay::fuzz
