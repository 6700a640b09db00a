// The arm's PDO layout (docs/cia402.md): RPDO1/2 and TPDO1/2 round trips, units, range and DLC
// checks.
#include "drivers/arm/arm_pdo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "drivers/arm/cia402_state.h"

namespace topay::cia402 {
namespace {

const JointUnits kUnits;

TEST(ArmPdoTest, Rpdo1RoundTripsWithItsUnits) {
  const auto frame = EncodeRpdo1({3, 0x000F, 1.2345}, kUnits, nullptr);
  ASSERT_TRUE(frame);
  // 1.2345 rad/s = 12345 units of 0.1 mrad/s = 0x00003039.
  EXPECT_EQ(can::ToString(*frame), "203#0F0039300000");
  const auto back = DecodeRpdo1(*frame, kUnits, nullptr);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->node_id, 3);
  EXPECT_EQ(back->controlword, 0x000F);
  EXPECT_NEAR(back->target_velocity_rad_per_s, 1.2345, 1e-12);
  const auto negative = EncodeRpdo1({3, 0x0006, -2.35}, kUnits, nullptr);
  ASSERT_TRUE(negative);
  EXPECT_NEAR(DecodeRpdo1(*negative, kUnits, nullptr)->target_velocity_rad_per_s, -2.35, 1e-12);
}

TEST(ArmPdoTest, Rpdo2Tpdo1Tpdo2RoundTrip) {
  const auto rpdo2 = EncodeRpdo2({7, -1.5}, kUnits, nullptr);
  ASSERT_TRUE(rpdo2);
  EXPECT_EQ(rpdo2->id, 0x307u);
  EXPECT_EQ(rpdo2->dlc, 4);
  EXPECT_NEAR(DecodeRpdo2(*rpdo2, kUnits, nullptr)->target_position_rad, -1.5, 1e-12);

  const std::uint16_t status = EncodeStatusword(DriveState::kOperationEnabled);
  const auto tpdo1 = EncodeTpdo1({7, status, 0.000001}, kUnits, nullptr);
  ASSERT_TRUE(tpdo1);
  EXPECT_EQ(can::ToString(*tpdo1), "187#270001000000");
  const auto tpdo1_back = DecodeTpdo1(*tpdo1, kUnits, nullptr);
  ASSERT_TRUE(tpdo1_back);
  EXPECT_EQ(tpdo1_back->statusword, status);
  EXPECT_NEAR(tpdo1_back->position_rad, 1e-6, 1e-15);

  const auto tpdo2 = EncodeTpdo2({7, -0.0001}, kUnits, nullptr);
  ASSERT_TRUE(tpdo2);
  EXPECT_EQ(can::ToString(*tpdo2), "287#FFFFFFFF");
  EXPECT_NEAR(DecodeTpdo2(*tpdo2, kUnits, nullptr)->velocity_rad_per_s, -0.0001, 1e-15);
}

TEST(ArmPdoTest, OutOfRangeValuesAreRejected) {
  std::string error;
  EXPECT_FALSE(EncodeRpdo1({1, 0x0F, 2.36}, kUnits, &error));
  EXPECT_NE(error.find("RPDO1: target velocity (rad/s) 2.36"), std::string::npos) << error;
  EXPECT_FALSE(EncodeRpdo1({1, 0x0F, std::numeric_limits<double>::quiet_NaN()}, kUnits, &error));
  EXPECT_FALSE(EncodeRpdo1({1, 0x0F, std::numeric_limits<double>::infinity()}, kUnits, &error));
  EXPECT_FALSE(EncodeRpdo2({1, 7.0}, kUnits, &error));
  EXPECT_FALSE(EncodeTpdo2({1, -5.0}, kUnits, &error));
  EXPECT_FALSE(EncodeRpdo1({0, 0x0F, 0.0}, kUnits, &error));
  EXPECT_EQ(error, "RPDO1: node id 0 is outside 1..127");
  // 23501 units = 2.3501 rad/s: beyond the limit on the drive side too.
  EXPECT_FALSE(DecodeRpdo1(can::CanFrame::Standard(0x201, {0x0F, 0x00, 0xCD, 0x5B, 0, 0}),
                           kUnits, &error));
  EXPECT_EQ(error.rfind("RPDO1 frame '201#0F00CD5B0000': target velocity 23501 units is beyond "
                        "+-23500",
                        0),
            0u)
      << error;
  // Position 0x7FFFFFFF units = 2147 rad.
  EXPECT_FALSE(DecodeTpdo1(can::CanFrame::Standard(0x181, {0x27, 0x00, 0xFF, 0xFF, 0xFF, 0x7F}),
                           kUnits, &error));
  EXPECT_NE(error.find("position actual 2147483647 units"), std::string::npos) << error;
  // A statusword that encodes no state (0x0002: switched on without ready to switch on).
  EXPECT_FALSE(DecodeTpdo1(can::CanFrame::Standard(0x181, {0x02, 0x00, 0, 0, 0, 0}), kUnits,
                           &error));
  EXPECT_EQ(error, "TPDO1 frame '181#020000000000': statusword 0x0002: bits 0-3,5,6 = 0x02 "
                   "encode no CiA 402 state");
}

TEST(ArmPdoTest, WrongDlcAndIdsAreRejected) {
  std::string error;
  EXPECT_FALSE(DecodeRpdo1(can::CanFrame::Standard(0x201, {0x0F, 0, 0, 0, 0, 0, 0, 0}), kUnits,
                           &error));
  EXPECT_EQ(error, "RPDO1 frame '201#0F00000000000000': DLC 8, expected 6");
  EXPECT_FALSE(DecodeTpdo2(can::CanFrame::Standard(0x281, {0, 0}), kUnits, &error));
  EXPECT_EQ(error, "TPDO2 frame '281#0000': DLC 2, expected 4");
  EXPECT_FALSE(DecodeTpdo1(can::CanFrame::Standard(0x281, {0, 0, 0, 0, 0, 0}), kUnits, &error));
  EXPECT_EQ(error, "TPDO1 frame '281#000000000000': id 0x281 is TPDO2, expected TPDO1");
  EXPECT_FALSE(DecodeRpdo2(can::CanFrame::Standard(0x300, {0, 0, 0, 0}), kUnits, &error));
  EXPECT_NE(error.find("node id 0"), std::string::npos);
  EXPECT_FALSE(DecodeRpdo2(can::CanFrame::Standard(0x680, {0, 0, 0, 0}), kUnits, &error));
  EXPECT_NE(error.find("not a CANopen object this stack uses"), std::string::npos);
}

}  // namespace
}  // namespace topay::cia402
