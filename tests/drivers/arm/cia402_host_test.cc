// The host helper brings a drive model to Operation enabled from every state.
#include "drivers/arm/cia402_host.h"

#include <gtest/gtest.h>

#include "drivers/arm/cia402_drive_model.h"

namespace topay::cia402 {
namespace {

TEST(Cia402HostTest, StepForEachState) {
  EXPECT_EQ(NextStepTowardsOperationEnabled(DriveState::kSwitchOnDisabled, 0).controlword,
            0x0006);
  EXPECT_EQ(NextStepTowardsOperationEnabled(DriveState::kReadyToSwitchOn, 0x06).controlword,
            0x0007);
  EXPECT_EQ(NextStepTowardsOperationEnabled(DriveState::kSwitchedOn, 0x07).controlword, 0x000F);
  EXPECT_EQ(NextStepTowardsOperationEnabled(DriveState::kOperationEnabled, 0x0F).controlword,
            0x000F);
  EXPECT_EQ(NextStepTowardsOperationEnabled(DriveState::kQuickStopActive, 0x02).controlword,
            0x0000);
  EXPECT_EQ(NextStepTowardsOperationEnabled(DriveState::kFault, 0x0F).controlword, 0x0080);
  EXPECT_EQ(NextStepTowardsOperationEnabled(DriveState::kFault, 0x80).controlword, 0x0000);
  EXPECT_TRUE(NextStepTowardsOperationEnabled(DriveState::kNotReadyToSwitchOn, 0).waiting);
  EXPECT_TRUE(NextStepTowardsOperationEnabled(DriveState::kFaultReactionActive, 0).waiting);
}

// Puts a fresh model in `state` (with `last_controlword` the last one it received).
DriveModel ModelIn(DriveState state, std::uint16_t* last_controlword) {
  DriveModel model;
  *last_controlword = 0;
  auto send = [&](std::uint16_t cw) {
    model.ApplyControlword(cw);
    *last_controlword = cw;
  };
  if (state == DriveState::kNotReadyToSwitchOn) return model;
  model.CompleteInitialization();
  if (state == DriveState::kFaultReactionActive || state == DriveState::kFault) {
    send(0x0080);  // bit 7 already high when the fault comes: the host must clear it
    model.OnFault();
    if (state == DriveState::kFault) model.CompleteFaultReaction();
    return model;
  }
  if (state == DriveState::kSwitchOnDisabled) return model;
  send(0x06);
  if (state == DriveState::kReadyToSwitchOn) return model;
  send(0x07);
  if (state == DriveState::kSwitchedOn) return model;
  send(0x0F);
  if (state == DriveState::kQuickStopActive) send(0x02);
  return model;
}

TEST(Cia402HostTest, ReachesOperationEnabledFromEveryState) {
  for (DriveState start :
       {DriveState::kNotReadyToSwitchOn, DriveState::kSwitchOnDisabled,
        DriveState::kReadyToSwitchOn, DriveState::kSwitchedOn, DriveState::kOperationEnabled,
        DriveState::kQuickStopActive, DriveState::kFaultReactionActive, DriveState::kFault}) {
    SCOPED_TRACE(std::string(ToString(start)));
    std::uint16_t previous = 0;
    DriveModel model = ModelIn(start, &previous);
    ASSERT_EQ(model.state(), start);
    int cycles = 0;
    for (; cycles < 10 && model.state() != DriveState::kOperationEnabled; ++cycles) {
      // The host reads the state from the statusword, as from a TPDO1.
      const auto state = DecodeStatusword(model.statusword(), nullptr);
      ASSERT_TRUE(state);
      const HostStep step = NextStepTowardsOperationEnabled(*state, previous);
      if (step.waiting) {
        // The drive finishes its own transition (1 or 14) meanwhile.
        if (*state == DriveState::kNotReadyToSwitchOn) model.CompleteInitialization();
        if (*state == DriveState::kFaultReactionActive) model.CompleteFaultReaction();
      }
      const TransitionResult result = model.ApplyControlword(step.controlword);
      // The only refusals allowed are the ones the helper plans for: clearing bit 7 in Fault
      // (and 0x0000 sent while waiting for the fault reaction to end).
      if (!result.accepted) {
        EXPECT_TRUE(*state == DriveState::kFault || step.waiting) << result.reason;
      }
      previous = step.controlword;
    }
    EXPECT_EQ(model.state(), DriveState::kOperationEnabled);
    EXPECT_LE(cycles, 5);  // the longest: Fault with bit 7 already set
  }
}

}  // namespace
}  // namespace topay::cia402
