// The exact length of a classic CAN frame on the wire: CRC-15, the stuffed region's bits, stuff
// bits and the total, on frames checked by hand (and cross-checked with a second implementation
// that builds the stuffed bit stream by inserting the bits, see the values' derivations).
#include "drivers/can/can_frame_bits.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "drivers/can/can_error.h"

namespace topay::can {
namespace {

std::string BitString(const std::vector<std::uint8_t>& bits) {
  std::string text;
  for (const std::uint8_t bit : bits) text += bit ? '1' : '0';
  return text;
}

// All 34 bits of the stuffed region are 0 (SOF, id 0, RTR/IDE/r0, DLC 0, CRC 0 of all-zero bits):
// a stuff bit (1) after the first 5 zeros; each stuff bit is a run of one 1, then 5 more zeros
// need the next one: 34 = 5 + 5 * 5 + 4 -> 6 stuff bits. 34 + 6 + 13 = 53 bits.
TEST(CanFrameBitsTest, AllZeroStandardFrameByHand) {
  const CanFrame frame = CanFrame::Standard(0x000);
  const std::vector<std::uint8_t> region = CanFrameStuffedRegionBits(frame);
  EXPECT_EQ(BitString(region), std::string(34, '0'));
  EXPECT_EQ(CanCrc15(CanFrameHeaderAndDataBits(frame)), 0);
  EXPECT_EQ(CountStuffBits(region), 6);
  EXPECT_EQ(CanFrameLengthBits(frame), 53);
}

// 0x7FF, DLC 0: SOF 0, eleven 1s (a 0 stuffed after the 5th and the 10th), RTR IDE r0 DLC = seven
// 0s (a 1 stuffed after the 5th of the run that the last id bit's 1 does not join), then
// CRC 0x272F = 010 0111 0010 1111 (no run of 5): 3 stuff bits, 34 + 3 + 13 = 50 bits.
TEST(CanFrameBitsTest, AllOnesIdByHand) {
  const CanFrame frame = CanFrame::Standard(0x7FF);
  EXPECT_EQ(CanCrc15(CanFrameHeaderAndDataBits(frame)), 0x272F);
  EXPECT_EQ(BitString(CanFrameStuffedRegionBits(frame)), "0111111111110000000010011100101111");
  EXPECT_EQ(CountStuffBits(CanFrameStuffedRegionBits(frame)), 3);
  EXPECT_EQ(CanFrameLengthBits(frame), 50);
}

TEST(CanFrameBitsTest, StandardDataFrames) {
  // 123#DEADBEEF: 66 region bits, CRC 0x4E6B, 2 stuff bits.
  const CanFrame deadbeef = CanFrame::Standard(0x123, {0xDE, 0xAD, 0xBE, 0xEF});
  EXPECT_EQ(BitString(CanFrameStuffedRegionBits(deadbeef)),
            "000100100011000010011011110101011011011111011101111100111001101011");
  EXPECT_EQ(CanCrc15(CanFrameHeaderAndDataBits(deadbeef)), 0x4E6B);
  EXPECT_EQ(CanFrameLengthBits(deadbeef), 66 + 2 + 13);
  // Eight zero bytes: the worst case of a zero payload, 16 stuff bits (98 + 16 + 13).
  EXPECT_EQ(CanFrameLengthBits(CanFrame::Standard(0x000, {0, 0, 0, 0, 0, 0, 0, 0})), 127);
  EXPECT_EQ(CanCrc15(CanFrameHeaderAndDataBits(CanFrame::Standard(0x000, {0, 0, 0, 0, 0, 0, 0, 0}))), 0x145B);
  // 7FF#FFFFFFFFFFFFFFFF: 15 stuff bits.
  EXPECT_EQ(CanFrameLengthBits(CanFrame::Standard(0x7FF, {255, 255, 255, 255, 255, 255, 255, 255})), 126);
  // SYNC (080#) and an RPDO1 (201#0F0010270000) of this robot.
  EXPECT_EQ(CanFrameLengthBits(CanFrame::Standard(0x080)), 34 + 4 + 13);
  EXPECT_EQ(CanFrameLengthBits(CanFrame::Standard(0x201, {0x0F, 0, 0x10, 0x27, 0, 0})), 82 + 9 + 13);
}

TEST(CanFrameBitsTest, ExtendedAndRemoteFrames) {
  // 12345678#0102030405060708: 118 region bits (SRR, IDE, 18-bit extension, r1), CRC 0x221A.
  const CanFrame extended = CanFrame::Extended(0x12345678, {1, 2, 3, 4, 5, 6, 7, 8});
  EXPECT_EQ(CanFrameStuffedRegionBits(extended).size(), 118u);
  EXPECT_EQ(CanCrc15(CanFrameHeaderAndDataBits(extended)), 0x221A);
  EXPECT_EQ(CanFrameLengthBits(extended), 118 + 9 + 13);
  // 100#R2: RTR 1, DLC 2, no data.
  const CanFrame remote = CanFrame::Remote(0x100, 2);
  EXPECT_EQ(BitString(CanFrameStuffedRegionBits(remote)), "0001000000001000010000010101100100");
  EXPECT_EQ(CanFrameLengthBits(remote), 34 + 2 + 13);
}

TEST(CanFrameBitsTest, StuffBitStartsTheNextRun) {
  // 00000 then 1111: the stuffed 1 and four 1s make a run of 5 -> a second stuff bit.
  using Bits = std::vector<std::uint8_t>;
  EXPECT_EQ(CountStuffBits(Bits{0, 0, 0, 0, 0, 1, 1, 1, 1}), 2);
  EXPECT_EQ(CountStuffBits(Bits{0, 0, 0, 0, 1, 1, 1, 1}), 0);
  EXPECT_EQ(CountStuffBits(Bits{1, 1, 1, 1, 1}), 1);  // stuffed after the last bit too
}

// CanFrameLengthBits takes CRC and stuff bits a byte at a time through tables; the bit lists take
// them a bit at a time. Random frames of every kind and length, and payloads of long runs (the
// most stuffing), must give the same length both ways.
TEST(CanFrameBitsTest, TableLengthMatchesTheBitAtATimeLength) {
  std::mt19937 rng(11898);
  constexpr std::uint8_t kRunBytes[] = {0x00, 0xFF, 0x0F, 0xF0, 0x07, 0xE0, 0x83, 0x1F};
  for (int n = 0; n < 20000; ++n) {
    CanFrame frame;
    frame.extended = rng() % 2 == 0;
    frame.id = static_cast<std::uint32_t>(rng()) & (frame.extended ? CanFrame::kMaxExtendedId : CanFrame::kMaxStandardId);
    frame.remote = rng() % 8 == 0;
    frame.dlc = static_cast<std::uint8_t>(rng() % 9);
    const bool runs = rng() % 2 == 0;
    for (auto& byte : frame.data) byte = runs ? kRunBytes[rng() % 8] : static_cast<std::uint8_t>(rng());
    const std::vector<std::uint8_t> region = CanFrameStuffedRegionBits(frame);
    ASSERT_EQ(CanFrameLengthBits(frame), static_cast<int>(region.size()) + CountStuffBits(region) + kCanFrameTailBits)
        << ToString(frame);
  }
}

TEST(CanFrameBitsTest, BoundsOfEveryLength) {
  // Any 8-byte standard frame is 111..135 bits (docs/base_protocol.md), any empty one 47..55.
  for (std::uint32_t id = 0; id <= 0x7FF; id += 37) {
    for (int pattern = 0; pattern < 256; pattern += 51) {
      const auto b = static_cast<std::uint8_t>(pattern);
      const int eight = CanFrameLengthBits(CanFrame::Standard(id, {b, b, b, b, b, b, b, b}));
      EXPECT_GE(eight, 111);
      EXPECT_LE(eight, 135);
    }
    const int empty = CanFrameLengthBits(CanFrame::Standard(id));
    EXPECT_GE(empty, 47);
    EXPECT_LE(empty, 55);
  }
}

TEST(CanFrameBitsTest, ErrorAndInvalidFrames) {
  EXPECT_EQ(CanFrameLengthBits(MakeCanErrorFrame(0x40)), 0);
  CanFrame bad = CanFrame::Standard(1);
  bad.dlc = 9;
  EXPECT_THROW(CanFrameLengthBits(bad), std::invalid_argument);
}

}  // namespace
}  // namespace topay::can
