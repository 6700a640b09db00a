// Base protocol ids: function base + node id, names, lengths, identification of frames.
#include "drivers/base/protocol_ids.h"

#include <gtest/gtest.h>

namespace topay::base {
namespace {

TEST(ProtocolIdsTest, IdsAreFunctionBasePlusNodeId) {
  EXPECT_EQ(FrameId(BaseFrameKind::kFault, 1), 0x081u);
  EXPECT_EQ(FrameId(BaseFrameKind::kModeRequest, 1), 0x101u);
  EXPECT_EQ(FrameId(BaseFrameKind::kStatus, 1), 0x181u);
  EXPECT_EQ(FrameId(BaseFrameKind::kVelocityCommand, 1), 0x201u);
  EXPECT_EQ(FrameId(BaseFrameKind::kWheelSpeeds, 1), 0x281u);
  EXPECT_EQ(FrameId(BaseFrameKind::kOdometry, 127), 0x37Fu);
  EXPECT_EQ(FrameId(BaseFrameKind::kOdometry, 0), 0u);  // invalid node id
}

TEST(ProtocolIdsTest, NodeIdsAreOneTo127) {
  EXPECT_EQ(CheckNodeId(1), "");
  EXPECT_EQ(CheckNodeId(127), "");
  EXPECT_EQ(CheckNodeId(0), "node id 0 is outside 1..127");
  EXPECT_NE(CheckNodeId(128), "");
}

TEST(ProtocolIdsTest, NamesAndLengths) {
  EXPECT_STREQ(FrameName(BaseFrameKind::kVelocityCommand), "velocity command");
  EXPECT_EQ(FrameDlc(BaseFrameKind::kModeRequest), 2);
  EXPECT_EQ(FrameDlc(BaseFrameKind::kStatus), 8);
}

TEST(ProtocolIdsTest, IdentifiesFramesOfTheNode) {
  std::string error;
  EXPECT_EQ(IdentifyFrame(can::CanFrame::Standard(0x282, {}), 2, &error),
            BaseFrameKind::kWheelSpeeds);
  EXPECT_FALSE(IdentifyFrame(can::CanFrame::Standard(0x282, {}), 1, &error));
  EXPECT_EQ(error, "id 0x282 is not a base protocol frame of node 1");
  EXPECT_FALSE(IdentifyFrame(can::CanFrame::Standard(0x123, {}), 1, &error));
  EXPECT_FALSE(IdentifyFrame(can::CanFrame::Extended(0x201, {}), 1, &error));
  EXPECT_EQ(error, "not a base protocol frame: only standard data frames are used");
  EXPECT_FALSE(IdentifyFrame(can::CanFrame::Remote(0x201, 8), 1, &error));
  EXPECT_FALSE(IdentifyFrame(can::CanFrame::Standard(0x201, {}), 0, nullptr));  // no crash
}

}  // namespace
}  // namespace topay::base
