#include "drivers/arm/cia402_state.h"

#include <array>
#include <cstdio>

namespace topay::cia402 {
namespace {

struct StateCode {
  DriveState state;
  std::uint16_t mask;
  std::uint16_t value;
  std::string_view name;
};

// CiA 402-2 Table 31 (x = don't care):
//   Not ready to switch on  xxxx xxxx x0xx 0000
//   Switch on disabled      xxxx xxxx x1xx 0000
//   Ready to switch on      xxxx xxxx x01x 0001
//   Switched on             xxxx xxxx x01x 0011
//   Operation enabled       xxxx xxxx x01x 0111
//   Quick stop active       xxxx xxxx x00x 0111
//   Fault reaction active   xxxx xxxx x0xx 1111
//   Fault                   xxxx xxxx x0xx 1000
constexpr std::array<StateCode, 8> kStateCodes{{
    {DriveState::kNotReadyToSwitchOn, 0x4F, 0x00, "Not ready to switch on"},
    {DriveState::kSwitchOnDisabled, 0x4F, 0x40, "Switch on disabled"},
    {DriveState::kReadyToSwitchOn, 0x6F, 0x21, "Ready to switch on"},
    {DriveState::kSwitchedOn, 0x6F, 0x23, "Switched on"},
    {DriveState::kOperationEnabled, 0x6F, 0x27, "Operation enabled"},
    {DriveState::kQuickStopActive, 0x6F, 0x07, "Quick stop active"},
    {DriveState::kFaultReactionActive, 0x4F, 0x0F, "Fault reaction active"},
    {DriveState::kFault, 0x4F, 0x08, "Fault"},
}};

constexpr std::uint16_t kStateBits = 0x6F;  // bits 0-3, 5, 6

const StateCode& CodeOf(DriveState state) {
  for (const StateCode& code : kStateCodes) {
    if (code.state == state) return code;
  }
  return kStateCodes[0];  // unreachable
}

}  // namespace

std::string_view ToString(DriveState state) { return CodeOf(state).name; }

std::optional<DriveState> DecodeStatusword(std::uint16_t statusword, std::string* error) {
  for (const StateCode& code : kStateCodes) {
    if ((statusword & code.mask) == code.value) return code.state;
  }
  if (error != nullptr) {
    char text[96];
    std::snprintf(text, sizeof(text),
                  "statusword 0x%04X: bits 0-3,5,6 = 0x%02X encode no CiA 402 state",
                  static_cast<unsigned>(statusword),
                  static_cast<unsigned>(statusword & kStateBits));
    *error = text;
  }
  return std::nullopt;
}

std::uint16_t EncodeStatusword(DriveState state, std::uint16_t other_bits) {
  return static_cast<std::uint16_t>(CodeOf(state).value | (other_bits & ~kStateBits));
}

std::string_view ToString(Command command) {
  switch (command) {
    case Command::kShutdown: return "shutdown";
    case Command::kSwitchOn: return "switch on";
    case Command::kEnableOperation: return "enable operation";
    case Command::kDisableVoltage: return "disable voltage";
    case Command::kQuickStop: return "quick stop";
    case Command::kDisableOperation: return "disable operation";
    case Command::kFaultReset: return "fault reset";
  }
  return "unknown command";
}

std::uint16_t ControlwordOf(Command command) {
  switch (command) {
    case Command::kShutdown: return 0x0006;
    case Command::kSwitchOn: return 0x0007;
    case Command::kEnableOperation: return 0x000F;
    case Command::kDisableVoltage: return 0x0000;
    case Command::kQuickStop: return 0x0002;
    case Command::kDisableOperation: return 0x0007;
    case Command::kFaultReset: return 0x0080;
  }
  return 0x0000;
}

// CiA 402-2 Table 28, evaluated in the order that makes the x's unambiguous.
Command DecodeControlwordCommand(std::uint16_t controlword) {
  if ((controlword & controlword::kEnableVoltage) == 0) return Command::kDisableVoltage;
  if ((controlword & controlword::kQuickStop) == 0) return Command::kQuickStop;
  if ((controlword & controlword::kSwitchOn) == 0) return Command::kShutdown;
  if ((controlword & controlword::kEnableOperation) == 0) return Command::kSwitchOn;
  return Command::kEnableOperation;
}

bool IsFaultResetEdge(std::uint16_t previous, std::uint16_t current) {
  return (previous & controlword::kFaultReset) == 0 &&
         (current & controlword::kFaultReset) != 0;
}

}  // namespace topay::cia402
