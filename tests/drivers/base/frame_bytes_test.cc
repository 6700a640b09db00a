// The shared byte rules: little-endian fields, checksum, shape checks, scaling and counters.
#include "drivers/base/frame_bytes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace topay::base {
namespace {

TEST(FrameBytesTest, LittleEndianFields) {
  can::CanFrame frame = MakeEmptyFrame(BaseFrameKind::kStatus, 1);
  PutInt16Le(frame, 0, -2);
  PutUint16Le(frame, 2, 0x1234);
  PutUint24Le(frame, 4, 0xABCDEF12);  // only the low 24 bits
  EXPECT_EQ(frame.data[0], 0xFE);
  EXPECT_EQ(frame.data[1], 0xFF);
  EXPECT_EQ(frame.data[2], 0x34);
  EXPECT_EQ(frame.data[3], 0x12);
  EXPECT_EQ(frame.data[4], 0x12);
  EXPECT_EQ(frame.data[5], 0xEF);
  EXPECT_EQ(frame.data[6], 0xCD);
  EXPECT_EQ(GetInt16Le(frame, 0), -2);
  EXPECT_EQ(GetUint16Le(frame, 2), 0x1234);
  EXPECT_EQ(GetUint24Le(frame, 4), 0xCDEF12u);
}

TEST(FrameBytesTest, ChecksumCoversIdAndBytes) {
  can::CanFrame frame = MakeEmptyFrame(BaseFrameKind::kVelocityCommand, 1);  // id 0x201
  SealFrame(frame, 5);
  // 0xFF - ((0x01 + 0x02 + 5) & 0xFF) = 0xF7.
  EXPECT_EQ(frame.data[kChecksumByte], 0xF7);
  EXPECT_EQ(CheckFrameShape(frame, BaseFrameKind::kVelocityCommand, 1), "");
  frame.data[0] ^= 0x01;
  EXPECT_EQ(CheckFrameShape(frame, BaseFrameKind::kVelocityCommand, 1),
            "velocity command (0x201): bad checksum 247, expected 246");
}

TEST(FrameBytesTest, ShapeErrorsNameTheFrame) {
  can::CanFrame frame = MakeEmptyFrame(BaseFrameKind::kVelocityCommand, 1);
  SealFrame(frame, 0);
  frame.dlc = 6;
  EXPECT_EQ(CheckFrameShape(frame, BaseFrameKind::kVelocityCommand, 1),
            "velocity command (0x201): DLC 6, expected 8");
  EXPECT_EQ(CheckFrameShape(frame, BaseFrameKind::kStatus, 1),
            "status (0x181): wrong id 0x201");
  EXPECT_EQ(CheckFrameShape(frame, BaseFrameKind::kStatus, 200),
            "status: node id 200 is outside 1..127");
}

TEST(FrameBytesTest, ScalingRoundsToNearestAndRejectsOutOfRange) {
  std::string error;
  EXPECT_EQ(ScaleToRaw(0.0014, 1000, -3000, 3000, "v", &error), 1);
  EXPECT_EQ(ScaleToRaw(0.0015, 1000, -3000, 3000, "v", &error), 2);   // half away from zero
  EXPECT_EQ(ScaleToRaw(-0.0015, 1000, -3000, 3000, "v", &error), -2);
  EXPECT_EQ(ScaleToRaw(3.0004, 1000, -3000, 3000, "v", &error), 3000);  // rounds onto the limit
  EXPECT_FALSE(ScaleToRaw(3.0006, 1000, -3000, 3000, "v", &error));
  EXPECT_EQ(error, "v 3.0006 is outside -3..3");
  EXPECT_FALSE(ScaleToRaw(1e300, 1000, -3000, 3000, "v", &error));
  EXPECT_FALSE(ScaleToRaw(std::nan(""), 1000, -3000, 3000, "v", &error));
  EXPECT_EQ(error, "v is not finite");
  EXPECT_FALSE(
      ScaleToRaw(-std::numeric_limits<double>::infinity(), 1000, -3000, 3000, "v", nullptr));
}

TEST(FrameBytesTest, RollingCounterDetectsStaleFramesAndCountsGaps) {
  EXPECT_EQ(CheckRollingCounter("x", std::nullopt, 7), "");
  EXPECT_EQ(CheckRollingCounter("x", 6, 7), "");
  EXPECT_EQ(CheckRollingCounter("x", 7, 7), "x: counter 7 repeated (stale frame)");
  EXPECT_EQ(CounterGap(6, 7), 0);
  EXPECT_EQ(CounterGap(255, 0), 0);
  EXPECT_EQ(CounterGap(254, 1), 2);
  EXPECT_EQ(CounterGap(7, 7), 255);
}

}  // namespace
}  // namespace topay::base
