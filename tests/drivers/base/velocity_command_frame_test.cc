// The velocity command frame: layout, round trip over the range, rounding, rejection.
#include "drivers/base/velocity_command_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

can::CanFrame Encode(double v, double omega, std::uint8_t counter = 0, int node = 1) {
  std::string error;
  const auto frame = EncodeVelocityCommand({v, omega, counter}, node, &error);
  EXPECT_TRUE(frame) << error;
  return frame.value_or(can::CanFrame{});
}

TEST(VelocityCommandFrameTest, LayoutIsLittleEndianMillimetresAndMilliradians) {
  const can::CanFrame frame = Encode(1.0, -0.5, 9);
  EXPECT_EQ(frame.id, 0x201u);
  EXPECT_EQ(frame.dlc, 8);
  EXPECT_EQ(frame.data[0], 0xE8);  // 1000 = 0x03E8
  EXPECT_EQ(frame.data[1], 0x03);
  EXPECT_EQ(frame.data[2], 0x0C);  // -500 = 0xFE0C
  EXPECT_EQ(frame.data[3], 0xFE);
  EXPECT_EQ(frame.data[4], 0);
  EXPECT_EQ(frame.data[5], 0);
  EXPECT_EQ(frame.data[6], 9);
  EXPECT_EQ(frame.data[7], ComputeChecksum(frame));
  EXPECT_EQ(can::CheckCanFrame(frame), "");
}

TEST(VelocityCommandFrameTest, RoundTripOverTheRange) {
  std::string error;
  int count = 0;
  for (int v_mm = -3000; v_mm <= 3000; v_mm += 37) {
    for (int omega_mrad = -10000; omega_mrad <= 10000; omega_mrad += 433) {
      const auto counter = static_cast<std::uint8_t>(count++);
      const can::CanFrame frame = Encode(v_mm / 1000.0, omega_mrad / 1000.0, counter, 5);
      const auto decoded = DecodeVelocityCommand(frame, 5, std::nullopt, &error);
      ASSERT_TRUE(decoded) << error;
      EXPECT_EQ(std::lround(decoded->v_m_per_s * 1000), v_mm);
      EXPECT_EQ(std::lround(decoded->omega_rad_per_s * 1000), omega_mrad);
      EXPECT_EQ(decoded->counter, counter);
    }
  }
  // The extremes.
  for (const double v : {-3.0, 3.0}) {
    for (const double omega : {-10.0, 10.0}) {
      const auto decoded = DecodeVelocityCommand(Encode(v, omega), 1, std::nullopt, &error);
      ASSERT_TRUE(decoded) << error;
      EXPECT_DOUBLE_EQ(decoded->v_m_per_s, v);
      EXPECT_DOUBLE_EQ(decoded->omega_rad_per_s, omega);
    }
  }
}

TEST(VelocityCommandFrameTest, RoundsToTheNearestUnit) {
  std::string error;
  const auto decoded =
      DecodeVelocityCommand(Encode(0.12349, -0.00051), 1, std::nullopt, &error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_DOUBLE_EQ(decoded->v_m_per_s, 0.123);
  EXPECT_DOUBLE_EQ(decoded->omega_rad_per_s, -0.001);
  // Just inside the limit rounds onto it.
  EXPECT_TRUE(EncodeVelocityCommand({3.0004, 0.0, 0}, 1, &error));
}

TEST(VelocityCommandFrameTest, EncoderRejectsOutOfRangeValuesWithoutSaturating) {
  std::string error;
  EXPECT_FALSE(EncodeVelocityCommand({3.001, 0.0, 0}, 1, &error));
  EXPECT_EQ(error, "velocity command (0x201): v [m/s] 3.001 is outside -3..3");
  EXPECT_FALSE(EncodeVelocityCommand({0.0, -10.5, 0}, 1, &error));
  EXPECT_EQ(error, "velocity command (0x201): omega [rad/s] -10.5 is outside -10..10");
  EXPECT_FALSE(EncodeVelocityCommand({NAN, 0.0, 0}, 1, &error));
  EXPECT_EQ(error, "velocity command (0x201): v [m/s] is not finite");
  EXPECT_FALSE(EncodeVelocityCommand({0.0, 0.0, 0}, 0, &error));
  EXPECT_EQ(error, "velocity command: node id 0 is outside 1..127");
}

TEST(VelocityCommandFrameTest, DecoderRejectsMalformedFrames) {
  std::string error;
  can::CanFrame frame = Encode(0.5, 0.1, 3);
  can::CanFrame short_frame = frame;
  short_frame.dlc = 4;
  EXPECT_FALSE(DecodeVelocityCommand(short_frame, 1, std::nullopt, &error));
  EXPECT_EQ(error, "velocity command (0x201): DLC 4, expected 8");

  EXPECT_FALSE(DecodeVelocityCommand(frame, 2, std::nullopt, &error));  // another node's
  EXPECT_EQ(error, "velocity command (0x202): wrong id 0x201");

  can::CanFrame corrupted = frame;
  corrupted.data[1] ^= 0x40;
  EXPECT_FALSE(DecodeVelocityCommand(corrupted, 1, std::nullopt, &error));
  EXPECT_NE(error.find("velocity command (0x201): bad checksum"), std::string::npos) << error;

  can::CanFrame reserved = frame;
  reserved.data[4] = 1;
  SealFrame(reserved, 3);
  EXPECT_FALSE(DecodeVelocityCommand(reserved, 1, std::nullopt, &error));
  EXPECT_EQ(error, "velocity command (0x201): reserved bytes 4-5 are not zero");

  can::CanFrame too_fast = frame;
  PutInt16Le(too_fast, 0, 3001);
  SealFrame(too_fast, 3);
  EXPECT_FALSE(DecodeVelocityCommand(too_fast, 1, std::nullopt, &error));
  EXPECT_EQ(error, "velocity command (0x201): v [mm/s] 3001 is outside -3000..3000");

  can::CanFrame spinning = frame;
  PutInt16Le(spinning, 2, -32768);
  SealFrame(spinning, 3);
  EXPECT_FALSE(DecodeVelocityCommand(spinning, 1, std::nullopt, &error));
  EXPECT_EQ(error, "velocity command (0x201): omega [mrad/s] -32768 is outside -10000..10000");

  EXPECT_FALSE(DecodeVelocityCommand(can::CanFrame::Remote(0x201, 8), 1, std::nullopt, &error));
  EXPECT_EQ(error, "velocity command (0x201): not a standard data frame");
}

TEST(VelocityCommandFrameTest, RepeatedCounterIsStale) {
  std::string error;
  const can::CanFrame frame = Encode(0.5, 0.1, 42);
  EXPECT_TRUE(DecodeVelocityCommand(frame, 1, 41, &error));
  EXPECT_TRUE(DecodeVelocityCommand(frame, 1, 40, &error));  // a lost frame is not an error
  EXPECT_FALSE(DecodeVelocityCommand(frame, 1, 42, &error));
  EXPECT_EQ(error, "velocity command (0x201): counter 42 repeated (stale frame)");
  EXPECT_TRUE(DecodeVelocityCommand(Encode(0.5, 0.1, 0), 1, 255, &error));  // wraps
}

}  // namespace
}  // namespace topay::base
