#pragma once
// Little-endian packing of CAN frame data, shared by the protocols on the bus: CANopen (CiA 301
// §7.1.2: numbers are transferred least significant byte first) and the base's protocol.

#include <array>
#include <cstdint>

namespace topay::can {

/// Writes the low `size_bytes` (0..4) bytes of `value` at data[offset], least significant first.
inline void PutLittleEndian(std::uint32_t value, int size_bytes, int offset,
                            std::array<std::uint8_t, 8>* data) {
  for (int i = 0; i < size_bytes; ++i) {
    (*data)[offset + i] = static_cast<std::uint8_t>((value >> (8 * i)) & 0xFF);
  }
}

/// Reads `size_bytes` (0..4) bytes at data[offset], least significant first.
inline std::uint32_t GetLittleEndian(const std::array<std::uint8_t, 8>& data, int size_bytes,
                                     int offset) {
  std::uint32_t value = 0;
  for (int i = 0; i < size_bytes; ++i) {
    value |= static_cast<std::uint32_t>(data[offset + i]) << (8 * i);
  }
  return value;
}

}  // namespace topay::can
