// NMT node control (CiA 301 §7.2.8.3.1): encoding, decoding, malformed frames.
#include "drivers/arm/nmt.h"

#include <gtest/gtest.h>

namespace topay::canopen {
namespace {

TEST(NmtTest, EveryCommandRoundTrips) {
  for (NmtCommand command :
       {NmtCommand::kStartRemoteNode, NmtCommand::kStopRemoteNode,
        NmtCommand::kEnterPreOperational, NmtCommand::kResetNode,
        NmtCommand::kResetCommunication}) {
    for (int node : {0, 1, 127}) {
      const auto frame = EncodeNmt({command, node}, nullptr);
      ASSERT_TRUE(frame);
      EXPECT_EQ(frame->id, 0x000u);
      EXPECT_EQ(frame->dlc, 2);
      EXPECT_EQ(frame->data[0], static_cast<std::uint8_t>(command));
      EXPECT_EQ(frame->data[1], node);
      const auto back = DecodeNmt(*frame, nullptr);
      ASSERT_TRUE(back);
      EXPECT_EQ(back->command, command);
      EXPECT_EQ(back->node_id, node);
    }
  }
}

TEST(NmtTest, WireBytesFollowCia301) {
  EXPECT_EQ(can::ToString(*EncodeNmt({NmtCommand::kStartRemoteNode, 0}, nullptr)), "000#0100");
  EXPECT_EQ(can::ToString(*EncodeNmt({NmtCommand::kStopRemoteNode, 3}, nullptr)), "000#0203");
  EXPECT_EQ(can::ToString(*EncodeNmt({NmtCommand::kEnterPreOperational, 3}, nullptr)),
            "000#8003");
  EXPECT_EQ(can::ToString(*EncodeNmt({NmtCommand::kResetNode, 3}, nullptr)), "000#8103");
  EXPECT_EQ(can::ToString(*EncodeNmt({NmtCommand::kResetCommunication, 3}, nullptr)),
            "000#8203");
}

TEST(NmtTest, BadInputIsRejectedWithTheFrameNamed) {
  std::string error;
  EXPECT_FALSE(EncodeNmt({NmtCommand::kStartRemoteNode, 128}, &error));
  EXPECT_EQ(error, "NMT: node id 128 is outside 0..127 (0 = all nodes)");
  EXPECT_FALSE(EncodeNmt({static_cast<NmtCommand>(0x03), 1}, &error));
  EXPECT_EQ(error, "NMT: unknown command specifier 3");
  EXPECT_FALSE(DecodeNmt(can::CanFrame::Standard(0x000, {0x01}), &error));
  EXPECT_EQ(error, "NMT frame '000#01': DLC 1, expected 2");
  EXPECT_FALSE(DecodeNmt(can::CanFrame::Standard(0x000, {0x03, 0x01}), &error));
  EXPECT_EQ(error, "NMT frame '000#0301': unknown command specifier 3");
  EXPECT_FALSE(DecodeNmt(can::CanFrame::Standard(0x000, {0x01, 0x80}), &error));
  EXPECT_EQ(error, "NMT frame '000#0180': node id 128 is outside 0..127");
  EXPECT_FALSE(DecodeNmt(can::CanFrame::Standard(0x080, {0x01, 0x01}), &error));
  EXPECT_EQ(error, "NMT frame '080#0101': id 0x080 is SYNC, expected NMT");
}

}  // namespace
}  // namespace topay::canopen
