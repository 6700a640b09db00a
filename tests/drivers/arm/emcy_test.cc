// Emergency (CiA 301 §7.2.7): codec and malformed frames.
#include "drivers/arm/emcy.h"

#include <gtest/gtest.h>

namespace topay::canopen {
namespace {

TEST(EmcyTest, RoundTripsLittleEndian) {
  Emcy emcy;
  emcy.node_id = 3;
  emcy.error_code = emcy_code::kFollowingError;
  emcy.error_register = error_register::kGeneric | error_register::kCurrent;
  emcy.manufacturer_data = {1, 2, 3, 4, 5};
  const auto frame = EncodeEmcy(emcy, nullptr);
  ASSERT_TRUE(frame);
  EXPECT_EQ(can::ToString(*frame), "083#1186030102030405");
  const auto back = DecodeEmcy(*frame, nullptr);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->node_id, 3);
  EXPECT_EQ(back->error_code, 0x8611);
  EXPECT_EQ(back->error_register, 0x03);
  EXPECT_EQ(back->manufacturer_data, emcy.manufacturer_data);
}

TEST(EmcyTest, MalformedFramesAreRejected) {
  std::string error;
  EXPECT_FALSE(EncodeEmcy({0}, &error));
  EXPECT_EQ(error, "EMCY: node id 0 is outside 1..127");
  EXPECT_FALSE(DecodeEmcy(can::CanFrame::Standard(0x083, {0x00, 0x10, 0x01}), &error));
  EXPECT_EQ(error, "EMCY frame '083#001001': DLC 3, expected 8");
  EXPECT_FALSE(DecodeEmcy(can::CanFrame::Standard(0x080), &error));  // SYNC, not EMCY
  EXPECT_EQ(error, "EMCY frame '080#': id 0x080 is SYNC, expected EMCY");
  EXPECT_FALSE(DecodeEmcy(can::CanFrame::Standard(0x183, {0, 0, 0, 0, 0, 0, 0, 0}), &error));
  EXPECT_NE(error.find("is TPDO1, expected EMCY"), std::string::npos);
}

}  // namespace
}  // namespace topay::canopen

namespace topay::canopen {
namespace {

TEST(EmcyTest, CommunicationErrorsAreThe81xxCodesAndTheRpdoTimeout) {
  EXPECT_TRUE(IsCommunicationError(emcy_code::kHeartbeatError));
  EXPECT_TRUE(IsCommunicationError(emcy_code::kCanOverrun));
  EXPECT_TRUE(IsCommunicationError(0x8140));  // recovered from bus-off
  EXPECT_TRUE(IsCommunicationError(emcy_code::kRpdoTimeout));  // the host's setpoints stopped
  EXPECT_FALSE(IsCommunicationError(emcy_code::kPdoLengthError));
  EXPECT_FALSE(IsCommunicationError(0x8240));  // unexpected SYNC data length: a protocol error
  EXPECT_FALSE(IsCommunicationError(emcy_code::kCurrent));
  EXPECT_FALSE(IsCommunicationError(emcy_code::kFollowingError));
  EXPECT_FALSE(IsCommunicationError(emcy_code::kErrorResetOrNoError));
}

}  // namespace
}  // namespace topay::canopen
