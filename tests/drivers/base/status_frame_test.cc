// The status frame: round trip of every mode, fault word and battery voltages, rejections.
#include "drivers/base/status_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include "drivers/base/fault_codes.h"
#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

TEST(StatusFrameTest, RoundTripOverModesFaultsAndVoltages) {
  std::string error;
  int count = 0;
  for (std::uint8_t mode = 0; mode <= kMaxBaseModeCode; ++mode) {
    for (std::uint8_t code = 0; code <= kMaxFaultCode; ++code) {
      for (const double volts : {0.0, 0.01, 24.0, 48.37, 99.99, 100.0}) {
        BaseStatus status;
        status.mode = static_cast<BaseMode>(mode);
        status.error_code = code;
        status.fault_bits = code == 0 ? 0 : FaultBit(static_cast<BaseFault>(code));
        status.battery_voltage_v = volts;
        status.counter = static_cast<std::uint8_t>(count++);
        const auto frame = EncodeStatus(status, 1, &error);
        ASSERT_TRUE(frame) << error;
        EXPECT_EQ(frame->id, 0x181u);
        const auto decoded = DecodeStatus(*frame, 1, &error);
        ASSERT_TRUE(decoded) << error;
        EXPECT_EQ(decoded->mode, status.mode);
        EXPECT_EQ(decoded->error_code, code);
        EXPECT_EQ(decoded->fault_bits, status.fault_bits);
        EXPECT_NEAR(decoded->battery_voltage_v, volts, 1e-9);
        EXPECT_EQ(decoded->counter, status.counter);
      }
    }
  }
  BaseStatus all_faults;
  all_faults.mode = BaseMode::kFault;
  all_faults.fault_bits = kDefinedFaultBits;
  const auto frame = EncodeStatus(all_faults, 1, &error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(DecodeStatus(*frame, 1, &error)->fault_bits, kDefinedFaultBits);
}

TEST(StatusFrameTest, BatteryVoltageRoundsToTenMillivolts) {
  std::string error;
  BaseStatus status;
  status.battery_voltage_v = 25.1249;
  const auto frame = EncodeStatus(status, 1, &error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(GetUint16Le(*frame, 4), 2512);
  EXPECT_DOUBLE_EQ(DecodeStatus(*frame, 1, &error)->battery_voltage_v, 25.12);
}

TEST(StatusFrameTest, EncoderRejectsBadFields) {
  std::string error;
  BaseStatus status;
  status.battery_voltage_v = 100.01;
  EXPECT_FALSE(EncodeStatus(status, 1, &error));
  EXPECT_EQ(error, "status (0x181): battery voltage [V] 100.01 is outside 0..100");
  status.battery_voltage_v = -0.01;
  EXPECT_FALSE(EncodeStatus(status, 1, &error));
  status.battery_voltage_v = 24.0;
  status.error_code = 11;
  EXPECT_FALSE(EncodeStatus(status, 1, &error));
  EXPECT_EQ(error, "status (0x181): unknown error code 11");
  status.error_code = 0;
  status.fault_bits = 0x0400;
  EXPECT_FALSE(EncodeStatus(status, 1, &error));
  EXPECT_EQ(error, "status (0x181): undefined fault bits in 0x0400");
  status.fault_bits = 0;
  status.mode = static_cast<BaseMode>(4);
  EXPECT_FALSE(EncodeStatus(status, 1, &error));
  EXPECT_EQ(error, "status (0x181): unknown mode 4");
}

TEST(StatusFrameTest, DecoderRejectsMalformedFrames) {
  std::string error;
  BaseStatus status;
  status.battery_voltage_v = 24.0;
  const can::CanFrame good = *EncodeStatus(status, 1, &error);

  can::CanFrame bad_mode = good;
  bad_mode.data[0] = 9;
  SealFrame(bad_mode, 0);
  EXPECT_FALSE(DecodeStatus(bad_mode, 1, &error));
  EXPECT_EQ(error, "status (0x181): unknown mode 9");

  can::CanFrame bad_battery = good;
  PutUint16Le(bad_battery, 4, 10001);
  SealFrame(bad_battery, 0);
  EXPECT_FALSE(DecodeStatus(bad_battery, 1, &error));
  EXPECT_EQ(error, "status (0x181): battery [10 mV] 10001 is outside 0..10000");

  can::CanFrame corrupted = good;
  corrupted.data[5] ^= 0x80;
  EXPECT_FALSE(DecodeStatus(corrupted, 1, &error));
  EXPECT_NE(error.find("status (0x181): bad checksum"), std::string::npos) << error;

  can::CanFrame short_frame = good;
  short_frame.dlc = 7;
  EXPECT_FALSE(DecodeStatus(short_frame, 1, &error));
  EXPECT_EQ(error, "status (0x181): DLC 7, expected 8");
}

}  // namespace
}  // namespace topay::base
