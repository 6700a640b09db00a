// The base controller's mode state machine: legal and illegal transitions, the command
// watchdog, faults and their reset.
#include "drivers/base/mode_state_machine.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace topay::base {
namespace {

TEST(ModeStateMachineTest, StartsInStandbyAndEntersCanCommandMode) {
  ModeStateMachine machine;
  EXPECT_EQ(machine.mode(), BaseMode::kStandby);
  EXPECT_EQ(machine.AcceptVelocityCommand(0.0), "velocity command ignored in standby");
  EXPECT_EQ(machine.Request(ModeRequest::kCanCommand, 0.0), "");
  EXPECT_EQ(machine.mode(), BaseMode::kCanCommand);
  EXPECT_EQ(machine.AcceptVelocityCommand(0.005), "");
  EXPECT_EQ(machine.Request(ModeRequest::kCanCommand, 0.006), "");  // same mode: no-op
  EXPECT_EQ(machine.Request(ModeRequest::kStandby, 0.01), "");
  EXPECT_EQ(machine.mode(), BaseMode::kStandby);
}

TEST(ModeStateMachineTest, CommandsKeepTheWatchdogFed) {
  ModeStateMachine machine;
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 1.0), "");
  for (int i = 1; i <= 400; ++i) {  // 2 s at 200 Hz
    const double t = 1.0 + 0.005 * i;
    EXPECT_FALSE(machine.Step(t));
    EXPECT_EQ(machine.AcceptVelocityCommand(t), "");
  }
  EXPECT_EQ(machine.mode(), BaseMode::kCanCommand);
  EXPECT_EQ(machine.timeout_count(), 0);
}

TEST(ModeStateMachineTest, CommandTimeoutGivesQuickStop) {
  ModeStateMachine machine;
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 0.45), "");
  ASSERT_EQ(machine.AcceptVelocityCommand(0.5), "");
  EXPECT_FALSE(machine.Step(0.6));  // exactly 100 ms: still fine
  EXPECT_EQ(machine.mode(), BaseMode::kCanCommand);
  EXPECT_TRUE(machine.Step(0.601));
  EXPECT_EQ(machine.mode(), BaseMode::kQuickStop);
  EXPECT_EQ(machine.timeout_count(), 1);
  EXPECT_FALSE(machine.Step(0.7));  // reported once
  EXPECT_EQ(machine.AcceptVelocityCommand(0.7), "velocity command ignored in quick stop");
}

TEST(ModeStateMachineTest, WatchdogArmsAtTheModeRequest) {
  ModeStateMachine machine;
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 2.0), "");
  EXPECT_TRUE(machine.Step(2.2));  // no command at all after the request
  EXPECT_EQ(machine.mode(), BaseMode::kQuickStop);
}

TEST(ModeStateMachineTest, LateCommandIsRefusedAfterTheTimeout) {
  ModeStateMachine machine;
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 0.0), "");
  EXPECT_EQ(machine.AcceptVelocityCommand(0.15), "velocity command ignored in quick stop");
}

TEST(ModeStateMachineTest, TimeoutToStandbyWhenConfigured) {
  ModeStateMachineOptions options;
  options.command_timeout_s = 0.05;
  options.timeout_mode = BaseMode::kStandby;
  ModeStateMachine machine(options);
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 0.0), "");
  EXPECT_TRUE(machine.Step(0.051));
  EXPECT_EQ(machine.mode(), BaseMode::kStandby);
  EXPECT_EQ(machine.Request(ModeRequest::kCanCommand, 0.06), "");  // straight back
}

TEST(ModeStateMachineTest, QuickStopIsLeftThroughStandby) {
  ModeStateMachine machine;
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 0.0), "");
  EXPECT_EQ(machine.Request(ModeRequest::kQuickStop, 0.01), "");
  EXPECT_EQ(machine.Request(ModeRequest::kCanCommand, 0.02),
            "CAN command refused in quick stop: quick stop is left through standby");
  EXPECT_EQ(machine.mode(), BaseMode::kQuickStop);
  EXPECT_EQ(machine.Request(ModeRequest::kStandby, 0.03), "");
  EXPECT_EQ(machine.Request(ModeRequest::kCanCommand, 0.04), "");
  EXPECT_EQ(machine.mode(), BaseMode::kCanCommand);
}

TEST(ModeStateMachineTest, FaultHoldsUntilFaultReset) {
  ModeStateMachine machine;
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 0.0), "");
  machine.RaiseFault(BaseFault::kOverCurrent, 0.01);
  EXPECT_EQ(machine.mode(), BaseMode::kFault);
  EXPECT_EQ(machine.fault_bits(), 0x0001);
  EXPECT_EQ(machine.error_code(), 1);
  machine.RaiseFault(BaseFault::kUnderVoltage, 0.02);
  EXPECT_EQ(machine.fault_bits(), 0x0005);
  EXPECT_EQ(machine.error_code(), 3);
  EXPECT_EQ(machine.AcceptVelocityCommand(0.03), "velocity command ignored in fault");
  EXPECT_EQ(machine.Request(ModeRequest::kCanCommand, 0.03),
            "CAN command refused in fault: only a fault reset leaves fault");
  EXPECT_EQ(machine.Request(ModeRequest::kStandby, 0.03),
            "standby refused in fault: only a fault reset leaves fault");
  EXPECT_EQ(machine.Request(ModeRequest::kQuickStop, 0.03),
            "quick stop refused in fault: only a fault reset leaves fault");
  EXPECT_FALSE(machine.Step(10.0));  // no timeout in fault
  EXPECT_EQ(machine.Request(ModeRequest::kFaultReset, 10.0), "");
  EXPECT_EQ(machine.mode(), BaseMode::kStandby);
  EXPECT_EQ(machine.fault_bits(), 0);
  EXPECT_EQ(machine.error_code(), 0);
}

TEST(ModeStateMachineTest, FaultResetWithoutFaultIsRefused) {
  ModeStateMachine machine;
  EXPECT_EQ(machine.Request(ModeRequest::kFaultReset, 0.0),
            "fault reset refused in standby: there is no fault to reset");
  EXPECT_EQ(machine.mode(), BaseMode::kStandby);
}

TEST(ModeStateMachineTest, TimeGoingBackIsRefused) {
  ModeStateMachine machine({}, 5.0);
  EXPECT_EQ(machine.Request(ModeRequest::kCanCommand, 4.0),
            "CAN command refused in standby: time went back");
  ASSERT_EQ(machine.Request(ModeRequest::kCanCommand, 5.0), "");
  EXPECT_EQ(machine.AcceptVelocityCommand(4.9), "velocity command ignored: time went back");
  EXPECT_FALSE(machine.Step(4.0));
  EXPECT_EQ(machine.mode(), BaseMode::kCanCommand);
}

TEST(ModeStateMachineTest, InvalidOptionsThrow) {
  ModeStateMachineOptions options;
  options.command_timeout_s = 0.0;
  EXPECT_THROW(ModeStateMachine{options}, std::invalid_argument);
  options = ModeStateMachineOptions{};
  options.timeout_mode = BaseMode::kFault;
  EXPECT_EQ(CheckModeStateMachineOptions(options), "timeout_mode must be quick stop or standby");
}

}  // namespace
}  // namespace topay::base
