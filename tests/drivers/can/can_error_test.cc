// Error frames (linux/can/error.h) -> reports and bus states.
#include "drivers/can/can_error.h"

#include <linux/can/error.h>

#include <gtest/gtest.h>

#include "drivers/can/can_bus.h"

namespace topay::can {
namespace {

TEST(CanErrorTest, DecodesBusOff) {
  const CanErrorReport report = DecodeCanErrorFrame(MakeCanErrorFrame(CAN_ERR_BUSOFF));
  EXPECT_TRUE(report.bus_off);
  EXPECT_EQ(report.description, "bus-off");
  EXPECT_EQ(NextBusState(CanBusState::kErrorActive, report), CanBusState::kBusOff);
}

TEST(CanErrorTest, DecodesControllerLevels) {
  const CanErrorReport warning = DecodeCanErrorFrame(MakeCanErrorFrame(0, CAN_ERR_CRTL_RX_WARNING));
  EXPECT_TRUE(warning.controller);
  EXPECT_TRUE(warning.warning);
  EXPECT_EQ(warning.description, "controller: rx warning");
  EXPECT_EQ(NextBusState(CanBusState::kErrorActive, warning), CanBusState::kErrorWarning);

  const CanErrorReport passive =
      DecodeCanErrorFrame(MakeCanErrorFrame(CAN_ERR_ACK, CAN_ERR_CRTL_TX_PASSIVE | CAN_ERR_CRTL_TX_WARNING));
  EXPECT_TRUE(passive.passive);
  EXPECT_TRUE(passive.no_ack);
  EXPECT_EQ(passive.description, "controller: tx warning, tx passive; no ACK");
  EXPECT_EQ(NextBusState(CanBusState::kErrorWarning, passive), CanBusState::kErrorPassive);

  const CanErrorReport active = DecodeCanErrorFrame(MakeCanErrorFrame(0, CAN_ERR_CRTL_ACTIVE));
  EXPECT_EQ(NextBusState(CanBusState::kErrorPassive, active), CanBusState::kErrorActive);
}

TEST(CanErrorTest, BusOffIsLeftOnlyByARestart) {
  const CanErrorReport passive = DecodeCanErrorFrame(MakeCanErrorFrame(0, CAN_ERR_CRTL_RX_PASSIVE));
  EXPECT_EQ(NextBusState(CanBusState::kBusOff, passive), CanBusState::kBusOff);
  const CanErrorReport protocol = DecodeCanErrorFrame(MakeCanErrorFrame(CAN_ERR_PROT));
  EXPECT_EQ(NextBusState(CanBusState::kBusOff, protocol), CanBusState::kBusOff);
  EXPECT_EQ(NextBusState(CanBusState::kErrorWarning, protocol), CanBusState::kErrorWarning);  // no level info
  const CanErrorReport restarted = DecodeCanErrorFrame(MakeCanErrorFrame(CAN_ERR_RESTARTED));
  EXPECT_TRUE(restarted.restarted);
  EXPECT_EQ(NextBusState(CanBusState::kBusOff, restarted), CanBusState::kErrorActive);
}

TEST(CanErrorTest, CountersGiveTheLevel) {
  const CanErrorReport report = DecodeCanErrorFrame(MakeCanErrorFrame(CAN_ERR_PROT, 0, 130, 5));
  ASSERT_TRUE(report.tx_error_counter);
  EXPECT_EQ(*report.tx_error_counter, 130);
  EXPECT_EQ(*report.rx_error_counter, 5);
  EXPECT_EQ(NextBusState(CanBusState::kErrorActive, report), CanBusState::kErrorPassive);
  const CanErrorReport low = DecodeCanErrorFrame(MakeCanErrorFrame(CAN_ERR_PROT, 0, 10, 97));
  EXPECT_EQ(NextBusState(CanBusState::kErrorActive, low), CanBusState::kErrorWarning);
}

TEST(CanErrorTest, NonErrorFrameGivesAnEmptyReport) {
  const CanErrorReport report = DecodeCanErrorFrame(CanFrame::Standard(0x40));
  EXPECT_FALSE(report.bus_off);
  EXPECT_EQ(report.description, "");
}

TEST(CanErrorTest, ApplyErrorFrameCountsAndTracksState) {
  CanBusStatus status;
  ApplyErrorFrame(MakeCanErrorFrame(CAN_ERR_BUSOFF), &status);
  ApplyErrorFrame(MakeCanErrorFrame(CAN_ERR_BUSOFF), &status);
  EXPECT_EQ(status.state, CanBusState::kBusOff);
  EXPECT_EQ(status.error_frames, 2u);
  EXPECT_EQ(status.bus_off_count, 1u);  // entered once
  EXPECT_EQ(status.last_error, "bus-off");
  ApplyErrorFrame(MakeCanErrorFrame(CAN_ERR_RESTARTED), &status);
  EXPECT_EQ(status.state, CanBusState::kErrorActive);
  ApplyErrorFrame(CanFrame::Standard(0x1), &status);  // not an error frame: no-op
  EXPECT_EQ(status.error_frames, 3u);
  EXPECT_STREQ(ToString(CanBusState::kErrorPassive), "error-passive");
}

}  // namespace
}  // namespace topay::can
