#include "drivers/arm/cia402_host.h"

namespace topay::cia402 {

HostStep NextStepTowardsOperationEnabled(DriveState state, std::uint16_t previous_controlword) {
  switch (state) {
    case DriveState::kNotReadyToSwitchOn:
      return {0x0000, "wait: the drive is initialising", true};
    case DriveState::kSwitchOnDisabled:
      return {ControlwordOf(Command::kShutdown), "shutdown (transition 2)", false};
    case DriveState::kReadyToSwitchOn:
      return {ControlwordOf(Command::kSwitchOn), "switch on (transition 3)", false};
    case DriveState::kSwitchedOn:
      return {ControlwordOf(Command::kEnableOperation), "enable operation (transition 4)", false};
    case DriveState::kOperationEnabled:
      return {ControlwordOf(Command::kEnableOperation), "hold operation enabled", false};
    case DriveState::kQuickStopActive:
      return {ControlwordOf(Command::kDisableVoltage), "disable voltage (transition 12)", false};
    case DriveState::kFaultReactionActive:
      return {0x0000, "wait: fault reaction in progress", true};
    case DriveState::kFault:
      if ((previous_controlword & controlword::kFaultReset) != 0) {
        return {0x0000, "clear bit 7 before the fault reset edge", false};
      }
      return {ControlwordOf(Command::kFaultReset), "fault reset (transition 15)", false};
  }
  return {0x0000, "unknown state", true};
}

}  // namespace topay::cia402
