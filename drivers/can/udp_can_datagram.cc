#include "drivers/can/udp_can_datagram.h"

namespace topay::can {
namespace {

constexpr std::uint8_t kMagic[4] = {'T', 'C', 'A', 'N'};
constexpr std::size_t kFrameOffset = 16;

void PutU32(std::uint32_t value, std::uint8_t* out) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

std::uint32_t GetU32(const std::uint8_t* in) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | in[i];
  return value;
}

bool Fail(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

}  // namespace

std::array<std::uint8_t, kUdpCanDatagramBytes> EncodeUdpCanDatagram(const UdpCanDatagram& datagram) {
  const struct can_frame frame = ToLinuxFrame(datagram.frame);  // throws when invalid
  std::array<std::uint8_t, kUdpCanDatagramBytes> out{};
  for (int i = 0; i < 4; ++i) out[i] = kMagic[i];
  out[4] = kUdpCanDatagramVersion;
  PutU32(datagram.sender_id, &out[8]);
  PutU32(datagram.sequence, &out[12]);
  PutU32(frame.can_id, &out[kFrameOffset]);
  out[kFrameOffset + 4] = frame.len;
  for (int i = 0; i < CAN_MAX_DLEN; ++i) out[kFrameOffset + 8 + i] = frame.data[i];
  return out;
}

std::optional<UdpCanDatagram> DecodeUdpCanDatagram(const std::uint8_t* bytes, std::size_t size,
                                                   std::string* error) {
  if (size != kUdpCanDatagramBytes) {
    Fail(error, "size " + std::to_string(size) + " bytes, expected " + std::to_string(kUdpCanDatagramBytes));
    return std::nullopt;
  }
  for (int i = 0; i < 4; ++i) {
    if (bytes[i] != kMagic[i]) {
      Fail(error, "bad magic (not a TCAN datagram)");
      return std::nullopt;
    }
  }
  if (bytes[4] != kUdpCanDatagramVersion) {
    Fail(error, "unsupported version " + std::to_string(bytes[4]));
    return std::nullopt;
  }
  struct can_frame frame{};
  frame.can_id = GetU32(&bytes[kFrameOffset]);
  frame.len = bytes[kFrameOffset + 4];
  for (int i = 0; i < CAN_MAX_DLEN; ++i) frame.data[i] = bytes[kFrameOffset + 8 + i];
  std::string why;
  const std::optional<CanFrame> decoded = FromLinuxFrame(frame, &why);
  if (!decoded) {
    Fail(error, "frame: " + why);
    return std::nullopt;
  }
  return UdpCanDatagram{GetU32(&bytes[8]), GetU32(&bytes[12]), *decoded};
}

}  // namespace topay::can
