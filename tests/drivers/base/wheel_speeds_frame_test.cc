// The wheel speeds frame: round trip over the range, rounding, rejections.
#include "drivers/base/wheel_speeds_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

TEST(WheelSpeedsFrameTest, RoundTripOverTheRange) {
  std::string error;
  for (int left = -30000; left <= 30000; left += 1237) {
    for (int right = -30000; right <= 30000; right += 2999) {
      const WheelSpeedsFeedback speeds{left / 1000.0, right / 1000.0, 77};
      const auto frame = EncodeWheelSpeeds(speeds, 1, &error);
      ASSERT_TRUE(frame) << error;
      EXPECT_EQ(frame->id, 0x281u);
      const auto decoded = DecodeWheelSpeeds(*frame, 1, &error);
      ASSERT_TRUE(decoded) << error;
      EXPECT_EQ(std::lround(decoded->left_rad_per_s * 1000), left);
      EXPECT_EQ(std::lround(decoded->right_rad_per_s * 1000), right);
      EXPECT_EQ(decoded->counter, 77);
    }
  }
  const auto extreme = EncodeWheelSpeeds({30.0, -30.0, 0}, 1, &error);
  ASSERT_TRUE(extreme) << error;
  EXPECT_DOUBLE_EQ(DecodeWheelSpeeds(*extreme, 1, &error)->right_rad_per_s, -30.0);
}

TEST(WheelSpeedsFrameTest, RoundsToMilliradiansPerSecond) {
  std::string error;
  const auto frame = EncodeWheelSpeeds({1.23451, -0.0004, 0}, 1, &error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(GetInt16Le(*frame, 0), 1235);
  EXPECT_EQ(GetInt16Le(*frame, 2), 0);
}

TEST(WheelSpeedsFrameTest, RejectsOutOfRangeAndMalformed) {
  std::string error;
  EXPECT_FALSE(EncodeWheelSpeeds({30.001, 0.0, 0}, 1, &error));
  EXPECT_EQ(error, "wheel speeds (0x281): left wheel speed [rad/s] 30.001 is outside -30..30");
  EXPECT_FALSE(EncodeWheelSpeeds({0.0, INFINITY, 0}, 1, &error));
  EXPECT_EQ(error, "wheel speeds (0x281): right wheel speed [rad/s] is not finite");

  can::CanFrame frame = *EncodeWheelSpeeds({1.0, 1.0, 0}, 1, &error);
  PutInt16Le(frame, 2, 30001);
  SealFrame(frame, 0);
  EXPECT_FALSE(DecodeWheelSpeeds(frame, 1, &error));
  EXPECT_EQ(error, "wheel speeds (0x281): right wheel [mrad/s] 30001 is outside -30000..30000");
  frame.dlc = 0;
  EXPECT_FALSE(DecodeWheelSpeeds(frame, 1, &error));
  EXPECT_EQ(error, "wheel speeds (0x281): DLC 0, expected 8");
  frame = *EncodeWheelSpeeds({1.0, 1.0, 0}, 1, &error);
  frame.data[6] = 1;  // counter changed without a new checksum
  EXPECT_FALSE(DecodeWheelSpeeds(frame, 1, &error));
  EXPECT_NE(error.find("bad checksum"), std::string::npos) << error;
}

}  // namespace
}  // namespace topay::base
