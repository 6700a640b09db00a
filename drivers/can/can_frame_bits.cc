#include "drivers/can/can_frame_bits.h"

#include <stdexcept>

namespace topay::can {
namespace {

void AppendBits(std::uint32_t value, int count, std::vector<std::uint8_t>* bits) {
  for (int i = count - 1; i >= 0; --i) bits->push_back(static_cast<std::uint8_t>((value >> i) & 1u));
}

}  // namespace

std::uint16_t CanCrc15(const std::vector<std::uint8_t>& bits) {
  std::uint16_t crc = 0;
  for (const std::uint8_t bit : bits) {
    const bool next = ((crc >> 14) & 1u) != (bit & 1u);
    crc = static_cast<std::uint16_t>((crc << 1) & 0x7FFF);
    if (next) crc ^= 0x4599;
  }
  return crc;
}

std::vector<std::uint8_t> CanFrameHeaderAndDataBits(const CanFrame& frame) {
  if (frame.error) throw std::invalid_argument("an error frame has no bits on the wire");
  if (const std::string problem = CheckCanFrame(frame); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  std::vector<std::uint8_t> bits;
  bits.reserve(128);
  bits.push_back(0);  // SOF
  const std::uint8_t rtr = frame.remote ? 1 : 0;
  if (frame.extended) {
    AppendBits(frame.id >> 18, 11, &bits);  // base id
    bits.push_back(1);                      // SRR
    bits.push_back(1);                      // IDE
    AppendBits(frame.id & 0x3FFFF, 18, &bits);
    bits.push_back(rtr);
    bits.push_back(0);  // r1
    bits.push_back(0);  // r0
  } else {
    AppendBits(frame.id, 11, &bits);
    bits.push_back(rtr);
    bits.push_back(0);  // IDE
    bits.push_back(0);  // r0
  }
  AppendBits(frame.dlc, 4, &bits);
  if (!frame.remote) {
    for (int i = 0; i < frame.dlc; ++i) AppendBits(frame.data[i], 8, &bits);
  }
  return bits;
}

std::vector<std::uint8_t> CanFrameStuffedRegionBits(const CanFrame& frame) {
  std::vector<std::uint8_t> bits = CanFrameHeaderAndDataBits(frame);
  AppendBits(CanCrc15(bits), 15, &bits);
  return bits;
}

int CountStuffBits(const std::vector<std::uint8_t>& bits) {
  int stuffed = 0;
  int run = 0;
  std::uint8_t last = 2;  // no bit yet
  for (const std::uint8_t bit : bits) {
    if (bit == last) {
      ++run;
    } else {
      last = bit;
      run = 1;
    }
    if (run == 5) {
      ++stuffed;
      last = static_cast<std::uint8_t>(1 - bit);  // the stuff bit starts the next run
      run = 1;
    }
  }
  return stuffed;
}

int CanFrameLengthBits(const CanFrame& frame) {
  if (frame.error) return 0;
  const std::vector<std::uint8_t> region = CanFrameStuffedRegionBits(frame);
  return static_cast<int>(region.size()) + CountStuffBits(region) + kCanFrameTailBits;
}

}  // namespace topay::can
