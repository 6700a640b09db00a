// The fault (emergency) frame: every fault round trips, inconsistent reports are refused.
#include "drivers/base/fault_frame.h"

#include <gtest/gtest.h>

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

TEST(FaultFrameTest, EveryFaultRoundTrips) {
  std::string error;
  for (std::uint8_t code = 1; code <= kMaxFaultCode; ++code) {
    FaultReport report;
    report.fault = static_cast<BaseFault>(code);
    report.fault_bits = FaultBit(report.fault) | FaultBit(BaseFault::kUnderVoltage);
    report.counter = code;
    const auto frame = EncodeFault(report, 1, &error);
    ASSERT_TRUE(frame) << error;
    EXPECT_EQ(frame->id, 0x081u);
    const auto decoded = DecodeFault(*frame, 1, &error);
    ASSERT_TRUE(decoded) << error;
    EXPECT_EQ(decoded->fault, report.fault);
    EXPECT_EQ(decoded->mode, BaseMode::kFault);
    EXPECT_EQ(decoded->fault_bits, report.fault_bits);
    EXPECT_EQ(decoded->counter, code);
  }
}

TEST(FaultFrameTest, NamesAndBits) {
  EXPECT_EQ(FaultBit(BaseFault::kOverCurrent), 0x0001);
  EXPECT_EQ(FaultBit(BaseFault::kRightMotorStall), 0x0200);
  EXPECT_STREQ(FaultCodeName(7), "emergency stop input");
  EXPECT_STREQ(FaultCodeName(0), "no fault");
  EXPECT_STREQ(FaultCodeName(200), "unknown fault");
  EXPECT_EQ(DescribeFaultBits(0x0005), "over-current, under-voltage");
  EXPECT_EQ(DescribeFaultBits(0), "none");
}

TEST(FaultFrameTest, RejectsInconsistentReports) {
  std::string error;
  FaultReport report;
  report.fault = BaseFault::kEncoderFault;
  report.fault_bits = FaultBit(BaseFault::kOverCurrent);
  EXPECT_FALSE(EncodeFault(report, 1, &error));
  EXPECT_EQ(error, "fault (0x081): fault word lacks the bit of the raised fault (encoder fault)");
  report.fault = static_cast<BaseFault>(0);
  EXPECT_FALSE(EncodeFault(report, 1, &error));
  EXPECT_EQ(error, "fault (0x081): unknown fault code 0");

  report.fault = BaseFault::kCanBusError;
  report.fault_bits = FaultBit(report.fault);
  can::CanFrame frame = *EncodeFault(report, 1, &error);
  frame.data[1] = 5;
  SealFrame(frame, 0);
  EXPECT_FALSE(DecodeFault(frame, 1, &error));
  EXPECT_EQ(error, "fault (0x081): unknown mode 5");
  frame = *EncodeFault(report, 1, &error);
  frame.data[5] = 1;
  SealFrame(frame, 0);
  EXPECT_FALSE(DecodeFault(frame, 1, &error));
  EXPECT_EQ(error, "fault (0x081): reserved bytes 4-5 are not zero");
  frame = *EncodeFault(report, 1, &error);
  frame.data[3] = 0x80;  // undefined bit, checksum still sealed below
  SealFrame(frame, 0);
  EXPECT_FALSE(DecodeFault(frame, 1, &error));
  EXPECT_EQ(error, "fault (0x081): undefined fault bits in 0x8080");
}

}  // namespace
}  // namespace topay::base
