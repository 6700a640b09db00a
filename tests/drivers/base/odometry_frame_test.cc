// The odometry frame: 24-bit wrapping tick counts, their differences, stale frames.
#include "drivers/base/odometry_frame.h"

#include <gtest/gtest.h>

namespace topay::base {
namespace {

TEST(OdometryFrameTest, RoundTripOfTickCounts) {
  std::string error;
  for (const std::uint32_t ticks : {0u, 1u, 123456u, 0x7FFFFFu, 0x800000u, 0xFFFFFFu}) {
    const auto frame = EncodeOdometry({ticks, 0xFFFFFFu - ticks, 200}, 1, &error);
    ASSERT_TRUE(frame) << error;
    EXPECT_EQ(frame->id, 0x301u);
    const auto decoded = DecodeOdometry(*frame, 1, std::nullopt, &error);
    ASSERT_TRUE(decoded) << error;
    EXPECT_EQ(decoded->left_ticks, ticks);
    EXPECT_EQ(decoded->right_ticks, 0xFFFFFFu - ticks);
    EXPECT_EQ(decoded->counter, 200);
  }
}

TEST(OdometryFrameTest, CountsWrapAt24Bits) {
  std::string error;
  const auto frame = EncodeOdometry({0x1000005u, 0u, 0}, 1, &error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(DecodeOdometry(*frame, 1, std::nullopt, &error)->left_ticks, 5u);
}

TEST(OdometryFrameTest, TickDeltaAcrossTheWrap) {
  EXPECT_EQ(WheelTickDelta(100, 150), 50);
  EXPECT_EQ(WheelTickDelta(150, 100), -50);
  EXPECT_EQ(WheelTickDelta(0xFFFFF0u, 0x10u), 0x20);
  EXPECT_EQ(WheelTickDelta(0x10u, 0xFFFFF0u), -0x20);
  EXPECT_EQ(WheelTickDelta(0, 0x7FFFFFu), 0x7FFFFF);
  EXPECT_EQ(WheelTickDelta(0, 0x800000u), -0x800000);
}

TEST(OdometryFrameTest, RejectsStaleAndMalformedFrames) {
  std::string error;
  const can::CanFrame frame = *EncodeOdometry({10, 20, 9}, 1, &error);
  EXPECT_TRUE(DecodeOdometry(frame, 1, 8, &error));
  EXPECT_FALSE(DecodeOdometry(frame, 1, 9, &error));
  EXPECT_EQ(error, "odometry (0x301): counter 9 repeated (stale frame)");
  can::CanFrame corrupted = frame;
  corrupted.data[2] = 0x55;
  EXPECT_FALSE(DecodeOdometry(corrupted, 1, std::nullopt, &error));
  EXPECT_NE(error.find("odometry (0x301): bad checksum"), std::string::npos) << error;
  EXPECT_FALSE(DecodeOdometry(can::CanFrame::Standard(0x301, {1, 2, 3}), 1, std::nullopt, &error));
  EXPECT_EQ(error, "odometry (0x301): DLC 3, expected 8");
  EXPECT_FALSE(EncodeOdometry({}, -1, &error));
  EXPECT_EQ(error, "odometry: node id -1 is outside 1..127");
}

}  // namespace
}  // namespace topay::base
