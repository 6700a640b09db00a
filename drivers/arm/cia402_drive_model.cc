#include "drivers/arm/cia402_drive_model.h"

#include <cstdio>

namespace topay::cia402 {
namespace {

std::string Hex4(std::uint16_t value) {
  char text[8];
  std::snprintf(text, sizeof(text), "0x%04X", static_cast<unsigned>(value));
  return text;
}

bool IsPowered(DriveState state) {
  return state == DriveState::kSwitchedOn || state == DriveState::kOperationEnabled ||
         state == DriveState::kQuickStopActive || state == DriveState::kFaultReactionActive;
}

}  // namespace

std::uint16_t DriveModel::statusword() const {
  return EncodeStatusword(state_, IsPowered(state_) ? statusword::kVoltageEnabled : 0);
}

TransitionResult DriveModel::Move(DriveState next, int transition) {
  state_ = next;
  return {true, state_, transition, ""};
}

TransitionResult DriveModel::Stay() const { return {true, state_, 0, ""}; }

TransitionResult DriveModel::Refuse(std::string reason) const {
  return {false, state_, 0, std::move(reason)};
}

TransitionResult DriveModel::ApplyControlword(std::uint16_t controlword) {
  const std::uint16_t previous = previous_controlword_;
  previous_controlword_ = controlword;
  if (state_ == DriveState::kFault) {
    if (IsFaultResetEdge(previous, controlword)) return Move(DriveState::kSwitchOnDisabled, 15);
    if ((controlword & controlword::kFaultReset) != 0) {
      return Refuse("controlword " + Hex4(controlword) +
                    " in Fault: fault reset acts on the 0->1 edge of bit 7, and bit 7 was "
                    "already set; clear it first");
    }
    return Refuse("controlword " + Hex4(controlword) +
                  " in Fault: only a fault reset (0->1 edge of bit 7) leaves Fault");
  }
  return ApplyCommand(DecodeControlwordCommand(controlword), controlword);
}

// CiA 402-2 Figure 25 and Table 29.
TransitionResult DriveModel::ApplyCommand(Command command, std::uint16_t controlword) {
  // Formatted only when refused: the drive applies a controlword with every RPDO1.
  const auto refuse = [&](std::string_view why) {
    return Refuse(std::string(ToString(command)) + " (controlword " + Hex4(controlword) + ") is illegal in " +
                  std::string(ToString(state_)) + std::string(why));
  };
  switch (state_) {
    case DriveState::kNotReadyToSwitchOn:
      return refuse(": the drive is still initialising");
    case DriveState::kFaultReactionActive:
      return refuse(": the fault reaction is in progress");
    case DriveState::kFault:
      return refuse("");  // handled by ApplyControlword
    case DriveState::kSwitchOnDisabled:
      if (command == Command::kShutdown) return Move(DriveState::kReadyToSwitchOn, 2);
      if (command == Command::kDisableVoltage || command == Command::kQuickStop) return Stay();
      return refuse(": send shutdown first");
    case DriveState::kReadyToSwitchOn:
      if (command == Command::kSwitchOn) return Move(DriveState::kSwitchedOn, 3);
      // "Switch on + enable operation" (0xxx 1111): transitions 3 and 4 at once.
      if (command == Command::kEnableOperation) return Move(DriveState::kOperationEnabled, 4);
      if (command == Command::kDisableVoltage || command == Command::kQuickStop) {
        return Move(DriveState::kSwitchOnDisabled, 7);
      }
      return Stay();  // shutdown
    case DriveState::kSwitchedOn:
      if (command == Command::kEnableOperation) return Move(DriveState::kOperationEnabled, 4);
      if (command == Command::kShutdown) return Move(DriveState::kReadyToSwitchOn, 6);
      if (command == Command::kDisableVoltage || command == Command::kQuickStop) {
        return Move(DriveState::kSwitchOnDisabled, 10);
      }
      return Stay();  // switch on
    case DriveState::kOperationEnabled:
      if (command == Command::kSwitchOn) return Move(DriveState::kSwitchedOn, 5);
      if (command == Command::kShutdown) return Move(DriveState::kReadyToSwitchOn, 8);
      if (command == Command::kDisableVoltage) return Move(DriveState::kSwitchOnDisabled, 9);
      if (command == Command::kQuickStop) return Move(DriveState::kQuickStopActive, 11);
      return Stay();  // enable operation
    case DriveState::kQuickStopActive:
      if (command == Command::kDisableVoltage) return Move(DriveState::kSwitchOnDisabled, 12);
      if (command == Command::kQuickStop) return Stay();
      if (command == Command::kEnableOperation && options_.quick_stop_stays_active) {
        return Move(DriveState::kOperationEnabled, 16);
      }
      return refuse(": send disable voltage (or wait for the stop to finish)");
  }
  return refuse("");
}

TransitionResult DriveModel::CompleteInitialization() {
  if (state_ != DriveState::kNotReadyToSwitchOn) {
    return Refuse("initialisation done in " + std::string(ToString(state_)) +
                  ": only from Not ready to switch on");
  }
  return Move(DriveState::kSwitchOnDisabled, 1);
}

TransitionResult DriveModel::OnFault() {
  if (state_ == DriveState::kFault || state_ == DriveState::kFaultReactionActive) return Stay();
  return Move(DriveState::kFaultReactionActive, 13);
}

TransitionResult DriveModel::CompleteFaultReaction() {
  if (state_ != DriveState::kFaultReactionActive) {
    return Refuse("fault reaction done in " + std::string(ToString(state_)) +
                  ": only from Fault reaction active");
  }
  return Move(DriveState::kFault, 14);
}

TransitionResult DriveModel::CompleteQuickStop() {
  if (state_ != DriveState::kQuickStopActive) {
    return Refuse("quick stop done in " + std::string(ToString(state_)) +
                  ": only from Quick stop active");
  }
  if (options_.quick_stop_stays_active) return Stay();
  return Move(DriveState::kSwitchOnDisabled, 12);
}

}  // namespace topay::cia402
