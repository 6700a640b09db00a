// The UDP bus datagram: its documented byte layout, round trip and malformed input.
#include "drivers/can/udp_can_datagram.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace topay::can {
namespace {

TEST(UdpCanDatagramTest, LayoutIsTheDocumentedOne) {
  const auto bytes = EncodeUdpCanDatagram({0x11223344, 0x01020304, CanFrame::Extended(0x1ABCDEF, {0xAA, 0xBB})});
  const std::uint8_t expected[32] = {
      'T', 'C', 'A', 'N', 1, 0, 0, 0,                   // magic, version, reserved
      0x44, 0x33, 0x22, 0x11, 0x04, 0x03, 0x02, 0x01,   // sender id, sequence (LE)
      0xEF, 0xCD, 0xAB, 0x81, 2, 0, 0, 0,               // can_id | CAN_EFF_FLAG (LE), len, pad
      0xAA, 0xBB, 0, 0, 0, 0, 0, 0};                    // data
  EXPECT_EQ(std::memcmp(bytes.data(), expected, sizeof(expected)), 0);
}

TEST(UdpCanDatagramTest, FrameBytesAreAStructCanFrameOnLittleEndianHosts) {
  const CanFrame frame = CanFrame::Standard(0x123, {1, 2, 3});
  const auto bytes = EncodeUdpCanDatagram({7, 9, frame});
  if constexpr (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__) {
    struct can_frame kernel{};
    std::memcpy(&kernel, bytes.data() + 16, sizeof(kernel));
    EXPECT_EQ(FromLinuxFrame(kernel, nullptr), frame);
  } else {
    GTEST_SKIP() << "big-endian host: the datagram stays little-endian, struct can_frame does not";
  }
}

TEST(UdpCanDatagramTest, RoundTrip) {
  for (const CanFrame& frame : {CanFrame::Standard(0x0), CanFrame::Standard(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}),
                                CanFrame::Remote(0x55, 4), CanFrame::Extended(0x1FFFFFFF)}) {
    const auto bytes = EncodeUdpCanDatagram({42, 0xFFFFFFFF, frame});
    std::string error;
    const std::optional<UdpCanDatagram> back = DecodeUdpCanDatagram(bytes.data(), bytes.size(), &error);
    ASSERT_TRUE(back) << error;
    EXPECT_EQ(back->sender_id, 42u);
    EXPECT_EQ(back->sequence, 0xFFFFFFFFu);
    EXPECT_EQ(back->frame, frame);
  }
}

TEST(UdpCanDatagramTest, MalformedDatagramsAreRejectedWithTheReason) {
  auto bytes = EncodeUdpCanDatagram({1, 2, CanFrame::Standard(0x123, {1})});
  std::string error;
  EXPECT_FALSE(DecodeUdpCanDatagram(bytes.data(), 16, &error));
  EXPECT_EQ(error, "size 16 bytes, expected 32");
  EXPECT_FALSE(DecodeUdpCanDatagram(bytes.data(), 0, &error));
  auto bad = bytes;
  bad[0] = 'X';
  EXPECT_FALSE(DecodeUdpCanDatagram(bad.data(), bad.size(), &error));
  EXPECT_EQ(error, "bad magic (not a TCAN datagram)");
  bad = bytes;
  bad[4] = 2;
  EXPECT_FALSE(DecodeUdpCanDatagram(bad.data(), bad.size(), &error));
  EXPECT_EQ(error, "unsupported version 2");
  bad = bytes;
  bad[20] = 9;  // DLC 9
  EXPECT_FALSE(DecodeUdpCanDatagram(bad.data(), bad.size(), &error));
  EXPECT_EQ(error, "frame: DLC 9 is above 8");
  bad = bytes;
  bad[17] = 0x08;  // standard id 0x823
  EXPECT_FALSE(DecodeUdpCanDatagram(bad.data(), bad.size(), &error));
  EXPECT_EQ(error, "frame: standard id 0x823 is above 0x7FF (use an extended id)");
}

TEST(UdpCanDatagramTest, EncodingAnInvalidFrameThrows) {
  CanFrame frame = CanFrame::Standard(1);
  frame.dlc = 9;
  EXPECT_THROW(EncodeUdpCanDatagram({1, 1, frame}), std::invalid_argument);
}

TEST(UdpCanDatagramTest, RandomBytesAreRejectedOrDecodedNeverCrash) {
  std::mt19937 random(20);
  const auto good = EncodeUdpCanDatagram({1, 2, CanFrame::Extended(0x100, {1, 2, 3})});
  int decoded = 0;
  for (int i = 0; i < 20000; ++i) {
    // Half: a valid datagram with a few random bytes flipped; half: random sizes and bytes.
    std::vector<std::uint8_t> bytes(good.begin(), good.end());
    if (i % 2 == 0) {
      for (int k = 0; k < 3; ++k) bytes[random() % bytes.size()] = static_cast<std::uint8_t>(random());
    } else {
      bytes.resize(random() % 64);
      for (std::uint8_t& byte : bytes) byte = static_cast<std::uint8_t>(random());
    }
    std::string error;
    const std::optional<UdpCanDatagram> datagram = DecodeUdpCanDatagram(bytes.data(), bytes.size(), &error);
    if (datagram) {
      ++decoded;
      EXPECT_EQ(CheckCanFrame(datagram->frame), "");
    } else {
      EXPECT_FALSE(error.empty());
    }
  }
  EXPECT_GT(decoded, 0);
}

}  // namespace
}  // namespace topay::can
