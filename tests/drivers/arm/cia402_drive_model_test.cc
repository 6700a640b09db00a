// The drive side of the CiA 402 state machine: every legal transition, illegal ones refused,
// the fault reset edge.
#include "drivers/arm/cia402_drive_model.h"

#include <gtest/gtest.h>

namespace topay::cia402 {
namespace {

// A model driven to `target` through legal transitions.
DriveModel ModelIn(DriveState target, DriveModelOptions options = {}) {
  DriveModel model(options);
  if (target == DriveState::kNotReadyToSwitchOn) return model;
  model.CompleteInitialization();
  switch (target) {
    case DriveState::kReadyToSwitchOn: model.ApplyControlword(0x06); break;
    case DriveState::kSwitchedOn:
      model.ApplyControlword(0x06);
      model.ApplyControlword(0x07);
      break;
    case DriveState::kOperationEnabled:
    case DriveState::kQuickStopActive:
      model.ApplyControlword(0x06);
      model.ApplyControlword(0x07);
      model.ApplyControlword(0x0F);
      if (target == DriveState::kQuickStopActive) model.ApplyControlword(0x02);
      break;
    case DriveState::kFaultReactionActive: model.OnFault(); break;
    case DriveState::kFault:
      model.OnFault();
      model.CompleteFaultReaction();
      break;
    default: break;
  }
  EXPECT_EQ(model.state(), target);
  return model;
}

struct Legal {
  DriveState from;
  std::uint16_t controlword;
  DriveState to;
  int transition;
};

TEST(Cia402DriveModelTest, EveryLegalControlwordTransition) {
  const Legal legal[] = {
      {DriveState::kSwitchOnDisabled, 0x0006, DriveState::kReadyToSwitchOn, 2},
      {DriveState::kReadyToSwitchOn, 0x0007, DriveState::kSwitchedOn, 3},
      {DriveState::kReadyToSwitchOn, 0x000F, DriveState::kOperationEnabled, 4},  // 3 + 4
      {DriveState::kSwitchedOn, 0x000F, DriveState::kOperationEnabled, 4},
      {DriveState::kOperationEnabled, 0x0007, DriveState::kSwitchedOn, 5},
      {DriveState::kSwitchedOn, 0x0006, DriveState::kReadyToSwitchOn, 6},
      {DriveState::kReadyToSwitchOn, 0x0000, DriveState::kSwitchOnDisabled, 7},
      {DriveState::kReadyToSwitchOn, 0x0002, DriveState::kSwitchOnDisabled, 7},
      {DriveState::kOperationEnabled, 0x0006, DriveState::kReadyToSwitchOn, 8},
      {DriveState::kOperationEnabled, 0x0000, DriveState::kSwitchOnDisabled, 9},
      {DriveState::kSwitchedOn, 0x0000, DriveState::kSwitchOnDisabled, 10},
      {DriveState::kSwitchedOn, 0x0002, DriveState::kSwitchOnDisabled, 10},
      {DriveState::kOperationEnabled, 0x0002, DriveState::kQuickStopActive, 11},
      {DriveState::kQuickStopActive, 0x0000, DriveState::kSwitchOnDisabled, 12},
      {DriveState::kFault, 0x0080, DriveState::kSwitchOnDisabled, 15},
  };
  for (const Legal& row : legal) {
    SCOPED_TRACE(std::string(ToString(row.from)) + " + " + std::to_string(row.controlword));
    DriveModel model = ModelIn(row.from);
    const TransitionResult result = model.ApplyControlword(row.controlword);
    EXPECT_TRUE(result.accepted) << result.reason;
    EXPECT_EQ(result.state, row.to);
    EXPECT_EQ(result.transition, row.transition);
    EXPECT_EQ(model.state(), row.to);
    EXPECT_EQ(DecodeStatusword(model.statusword(), nullptr), row.to);
  }
}

TEST(Cia402DriveModelTest, AutomaticTransitions) {
  DriveModel model;
  EXPECT_EQ(model.state(), DriveState::kNotReadyToSwitchOn);  // transition 0
  EXPECT_EQ(model.CompleteInitialization().transition, 1);
  EXPECT_EQ(model.state(), DriveState::kSwitchOnDisabled);
  EXPECT_FALSE(model.CompleteInitialization().accepted);
  for (DriveState from : {DriveState::kSwitchOnDisabled, DriveState::kReadyToSwitchOn,
                          DriveState::kSwitchedOn, DriveState::kOperationEnabled,
                          DriveState::kQuickStopActive, DriveState::kNotReadyToSwitchOn}) {
    DriveModel m = ModelIn(from);
    const TransitionResult fault = m.OnFault();
    EXPECT_EQ(fault.transition, 13) << ToString(from);
    EXPECT_EQ(m.state(), DriveState::kFaultReactionActive);
    EXPECT_EQ(m.CompleteFaultReaction().transition, 14);
    EXPECT_EQ(m.state(), DriveState::kFault);
  }
  DriveModel stopping = ModelIn(DriveState::kQuickStopActive);
  EXPECT_EQ(stopping.CompleteQuickStop().transition, 12);
  EXPECT_EQ(stopping.state(), DriveState::kSwitchOnDisabled);
  EXPECT_FALSE(stopping.CompleteQuickStop().accepted);
  EXPECT_FALSE(stopping.CompleteFaultReaction().accepted);
}

TEST(Cia402DriveModelTest, QuickStopOptionEnablesTransition16) {
  DriveModelOptions options;
  options.quick_stop_stays_active = true;
  DriveModel model = ModelIn(DriveState::kQuickStopActive, options);
  EXPECT_TRUE(model.CompleteQuickStop().accepted);
  EXPECT_EQ(model.state(), DriveState::kQuickStopActive);
  const TransitionResult result = model.ApplyControlword(0x000F);
  EXPECT_EQ(result.transition, 16);
  EXPECT_EQ(model.state(), DriveState::kOperationEnabled);
}

struct Illegal {
  DriveState from;
  std::uint16_t controlword;
  std::string_view reason_part;
};

TEST(Cia402DriveModelTest, IllegalTransitionsAreRefusedWithAReason) {
  const Illegal illegal[] = {
      {DriveState::kSwitchOnDisabled, 0x0007, "switch on (controlword 0x0007) is illegal in "
                                              "Switch on disabled: send shutdown first"},
      {DriveState::kSwitchOnDisabled, 0x000F, "enable operation (controlword 0x000F) is "
                                              "illegal in Switch on disabled"},
      {DriveState::kNotReadyToSwitchOn, 0x0006, "still initialising"},
      {DriveState::kFaultReactionActive, 0x0006, "fault reaction is in progress"},
      {DriveState::kFault, 0x000F, "only a fault reset (0->1 edge of bit 7) leaves Fault"},
      {DriveState::kFault, 0x0006, "only a fault reset"},
      {DriveState::kQuickStopActive, 0x000F, "is illegal in Quick stop active"},
      {DriveState::kQuickStopActive, 0x0006, "is illegal in Quick stop active"},
      {DriveState::kQuickStopActive, 0x0007, "is illegal in Quick stop active"},
  };
  for (const Illegal& row : illegal) {
    SCOPED_TRACE(std::string(ToString(row.from)) + " + " + std::to_string(row.controlword));
    DriveModel model = ModelIn(row.from);
    const TransitionResult result = model.ApplyControlword(row.controlword);
    EXPECT_FALSE(result.accepted);
    EXPECT_EQ(result.state, row.from);
    EXPECT_EQ(result.transition, 0);
    EXPECT_EQ(model.state(), row.from);
    EXPECT_NE(result.reason.find(row.reason_part), std::string::npos) << result.reason;
  }
}

TEST(Cia402DriveModelTest, RepeatingTheCurrentCommandIsANoOp) {
  DriveModel model = ModelIn(DriveState::kOperationEnabled);
  const TransitionResult hold = model.ApplyControlword(0x000F);
  EXPECT_TRUE(hold.accepted);
  EXPECT_EQ(hold.transition, 0);
  EXPECT_EQ(model.state(), DriveState::kOperationEnabled);
}

TEST(Cia402DriveModelTest, FaultResetActsOnTheRisingEdgeOnly) {
  DriveModel model = ModelIn(DriveState::kFault);
  // Bit 7 held from before the fault: no edge.
  DriveModel held = ModelIn(DriveState::kOperationEnabled);
  held.ApplyControlword(0x008F);  // bit 7 ignored outside Fault: stays enabled
  EXPECT_EQ(held.state(), DriveState::kOperationEnabled);
  held.OnFault();
  held.CompleteFaultReaction();
  TransitionResult result = held.ApplyControlword(0x0080);
  EXPECT_FALSE(result.accepted);
  EXPECT_NE(result.reason.find("bit 7 was already set"), std::string::npos) << result.reason;
  EXPECT_TRUE(held.ApplyControlword(0x0000).accepted == false);  // clearing: still Fault
  result = held.ApplyControlword(0x0080);
  EXPECT_TRUE(result.accepted);
  EXPECT_EQ(result.transition, 15);
  EXPECT_EQ(held.state(), DriveState::kSwitchOnDisabled);
  // A fresh edge with the other bits set also resets (0x0086: fault reset + shutdown bits);
  // the shutdown acts only on the next controlword.
  result = model.ApplyControlword(0x0086);
  EXPECT_EQ(result.transition, 15);
  EXPECT_EQ(model.state(), DriveState::kSwitchOnDisabled);
  EXPECT_EQ(model.ApplyControlword(0x0006).transition, 2);
  // Fault reaction active ignores the reset.
  DriveModel reacting = ModelIn(DriveState::kFaultReactionActive);
  EXPECT_FALSE(reacting.ApplyControlword(0x0080).accepted);
  EXPECT_EQ(reacting.state(), DriveState::kFaultReactionActive);
}

}  // namespace
}  // namespace topay::cia402
