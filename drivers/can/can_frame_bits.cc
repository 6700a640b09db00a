#include "drivers/can/can_frame_bits.h"

#include <array>
#include <stdexcept>

namespace topay::can {
namespace {

// A frame's stuffed region packed into one 128-bit word (at most SOF 1 + extended arbitration
// and control 38 + data 64 + CRC 15 = 118 bits; the first bit sent is the most significant of
// the `size` used), so that CanFrameLengthBits allocates nothing and takes CRC and stuff bits a
// byte at a time through tables. can_frame_bits_test.cc checks those against the bit-at-a-time
// CanCrc15 and CountStuffBits.
__extension__ typedef unsigned __int128 Word;

class PackedBits {
 public:
  void Append(std::uint32_t value, int count) {
    word_ = (word_ << count) | value;
    size_ += count;
  }
  int size() const { return size_; }
  unsigned BitAt(int i) const { return static_cast<unsigned>(word_ >> (size_ - 1 - i)) & 1u; }
  /// Bits i .. i + 7 as a byte (the first of them the most significant).
  unsigned ByteAt(int i) const { return static_cast<unsigned>(word_ >> (size_ - 8 - i)) & 0xFFu; }

 private:
  Word word_ = 0;
  int size_ = 0;
};

constexpr std::uint16_t kCrc15Polynomial = 0x4599;

// CRC-15 register after one bit (ISO 11898-1 §10.4.2.6: shift, XOR the polynomial when the bit
// shifted out differs from the next bit).
constexpr std::uint16_t Crc15Step(std::uint16_t crc, unsigned bit) {
  const bool next = ((crc >> 14) & 1u) != (bit & 1u);
  crc = static_cast<std::uint16_t>((crc << 1) & 0x7FFF);
  return next ? static_cast<std::uint16_t>(crc ^ kCrc15Polynomial) : crc;
}

// Byte table: entry i is the register after 8 zero bits from the register i << 7, so that 8 bits
// b at once give (crc << 8) ^ table[(crc >> 7) ^ b] (the usual MSB-first table CRC, width 15).
constexpr std::array<std::uint16_t, 256> MakeCrc15Table() {
  std::array<std::uint16_t, 256> table{};
  for (unsigned i = 0; i < 256; ++i) {
    auto crc = static_cast<std::uint16_t>(i << 7);
    for (int k = 0; k < 8; ++k) crc = Crc15Step(crc, 0);
    table[i] = crc;
  }
  return table;
}
constexpr std::array<std::uint16_t, 256> kCrc15Table = MakeCrc15Table();

// The stuffing rule's state between bits: 0 before the first bit, else 1 + 4 * last bit +
// (run length - 1) for runs of 1..4 equal bits (a run of 5 is stuffed and restarts at once).
struct StuffStep {
  std::uint8_t state;
  std::uint8_t stuffed;
};

constexpr StuffStep StuffBit(std::uint8_t state, unsigned bit) {
  const unsigned last = state == 0 ? 2u : (state - 1u) / 4u;
  unsigned run = state == 0 ? 0u : (state - 1u) % 4u + 1u;
  run = bit == last ? run + 1u : 1u;
  if (run == 5) return {static_cast<std::uint8_t>(1u + 4u * (1u - bit)), 1};  // the stuff bit is a run of 1
  return {static_cast<std::uint8_t>(1u + 4u * bit + (run - 1u)), 0};
}

// Byte table: for each state and byte, the state after its 8 bits and the stuff bits among them.
constexpr std::array<std::array<StuffStep, 256>, 9> MakeStuffTable() {
  std::array<std::array<StuffStep, 256>, 9> table{};
  for (unsigned state = 0; state < 9; ++state) {
    for (unsigned byte = 0; byte < 256; ++byte) {
      StuffStep step{static_cast<std::uint8_t>(state), 0};
      for (int k = 7; k >= 0; --k) {
        const StuffStep next = StuffBit(step.state, (byte >> k) & 1u);
        step = {next.state, static_cast<std::uint8_t>(step.stuffed + next.stuffed)};
      }
      table[state][byte] = step;
    }
  }
  return table;
}
constexpr std::array<std::array<StuffStep, 256>, 9> kStuffTable = MakeStuffTable();

// ISO 11898-1 §10.4 (frame formats): the bits from SOF to the end of the data field.
PackedBits PackedHeaderAndData(const CanFrame& frame) {
  if (frame.error) throw std::invalid_argument("an error frame has no bits on the wire");
  if (const std::string problem = CheckCanFrame(frame); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  PackedBits bits;
  const std::uint32_t rtr = frame.remote ? 1 : 0;
  if (frame.extended) {  // SOF, base id, SRR, IDE, extension, RTR, r1, r0, DLC
    bits.Append(0, 1);
    bits.Append(frame.id >> 18, 11);
    bits.Append(0b11, 2);
    bits.Append(frame.id & 0x3FFFF, 18);
    bits.Append(rtr << 2, 3);
  } else {  // SOF, id, RTR, IDE, r0
    bits.Append(0, 1);
    bits.Append(frame.id, 11);
    bits.Append(rtr << 2, 3);
  }
  bits.Append(frame.dlc, 4);
  if (!frame.remote) {
    for (int i = 0; i < frame.dlc; ++i) bits.Append(frame.data[i], 8);
  }
  return bits;
}

std::vector<std::uint8_t> Unpacked(const PackedBits& bits) {
  std::vector<std::uint8_t> list(static_cast<std::size_t>(bits.size()));
  for (int i = 0; i < bits.size(); ++i) list[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(bits.BitAt(i));
  return list;
}

std::uint16_t PackedCrc15(const PackedBits& bits) {
  std::uint16_t crc = 0;
  const int lead = bits.size() % 8;
  for (int i = 0; i < lead; ++i) crc = Crc15Step(crc, bits.BitAt(i));
  for (int i = lead; i < bits.size(); i += 8) {
    crc = static_cast<std::uint16_t>(((crc << 8) & 0x7FFF) ^ kCrc15Table[((crc >> 7) ^ bits.ByteAt(i)) & 0xFFu]);
  }
  return crc;
}

int PackedStuffBits(const PackedBits& bits) {
  StuffStep step{0, 0};
  int stuffed = 0;
  const int lead = bits.size() % 8;
  for (int i = 0; i < lead; ++i) {
    step = StuffBit(step.state, bits.BitAt(i));
    stuffed += step.stuffed;
  }
  for (int i = lead; i < bits.size(); i += 8) {
    step = kStuffTable[step.state][bits.ByteAt(i)];
    stuffed += step.stuffed;
  }
  return stuffed;
}

}  // namespace

std::uint16_t CanCrc15(std::span<const std::uint8_t> bits) {
  std::uint16_t crc = 0;
  for (const std::uint8_t bit : bits) crc = Crc15Step(crc, bit);
  return crc;
}

std::vector<std::uint8_t> CanFrameHeaderAndDataBits(const CanFrame& frame) {
  return Unpacked(PackedHeaderAndData(frame));
}

std::vector<std::uint8_t> CanFrameStuffedRegionBits(const CanFrame& frame) {
  std::vector<std::uint8_t> bits = CanFrameHeaderAndDataBits(frame);
  const std::uint16_t crc = CanCrc15(bits);
  for (int i = 14; i >= 0; --i) bits.push_back(static_cast<std::uint8_t>((crc >> i) & 1u));
  return bits;
}

int CountStuffBits(std::span<const std::uint8_t> bits) {
  StuffStep step{0, 0};
  int stuffed = 0;
  for (const std::uint8_t bit : bits) {
    step = StuffBit(step.state, bit & 1u);
    stuffed += step.stuffed;
  }
  return stuffed;
}

int CanFrameLengthBits(const CanFrame& frame) {
  if (frame.error) return 0;
  PackedBits region = PackedHeaderAndData(frame);
  region.Append(PackedCrc15(region), 15);
  return region.size() + PackedStuffBits(region) + kCanFrameTailBits;
}

}  // namespace topay::can
