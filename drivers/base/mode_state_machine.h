#pragma once
// The base controller's mode state machine (docs/base_protocol.md, "Modes"), as a pure class
// stepped with times: the motor simulator (server) runs it to decide what to do with requests
// and commands, the bridge (client) runs a copy to know what the base will do.
//
//   standby     --CAN command request-->  CAN command   (watchdog armed at the request time)
//   CAN command --standby request-->      standby
//   any but fault --quick stop request--> quick stop
//   quick stop  --standby request-->      standby        (never straight back to CAN command)
//   CAN command --no valid command for command_timeout_s--> timeout_mode (quick stop default)
//   any         --fault raised-->         fault
//   fault       --fault reset request-->  standby        (fault bits cleared)
// Every other request is refused with the reason; a request for the current mode is accepted
// and changes nothing.

#include <cstdint>
#include <string>

#include "drivers/base/base_mode.h"
#include "drivers/base/fault_codes.h"

namespace topay::base {

struct ModeStateMachineOptions {
  /// Longest gap between valid velocity commands in CAN command mode [s]. Default 0.1 s: 20
  /// periods of the bridge's 200 Hz commands (stack design: stop within 100 ms of silence).
  double command_timeout_s = 0.1;
  /// The mode after a command timeout: kQuickStop (default: brake at once) or kStandby.
  BaseMode timeout_mode = BaseMode::kQuickStop;
};

/// Empty when the options are valid (timeout finite and > 0, timeout mode quick stop or
/// standby), else what is wrong.
std::string CheckModeStateMachineOptions(const ModeStateMachineOptions& options);

class ModeStateMachine {
 public:
  /// Starts in standby, no faults, at time `start_time_s`. Throws std::invalid_argument with
  /// CheckModeStateMachineOptions' message for invalid options (a programming error).
  explicit ModeStateMachine(const ModeStateMachineOptions& options = {},
                            double start_time_s = 0.0);

  BaseMode mode() const { return mode_; }
  std::uint16_t fault_bits() const { return fault_bits_; }
  /// The most recent fault's code, 0 when none (status frame byte 1).
  std::uint8_t error_code() const { return error_code_; }
  /// How many command timeouts happened.
  int timeout_count() const { return timeout_count_; }

  /// Applies `request` at `time_s` (after Step(time_s)). Empty when accepted, else the reason
  /// it was refused, e.g. "fault reset refused in standby: there is no fault to reset".
  std::string Request(ModeRequest request, double time_s);

  /// A valid velocity command arrived at `time_s` (after Step(time_s)): feeds the watchdog.
  /// Empty when the base follows it (CAN command mode), else why it is ignored.
  std::string AcceptVelocityCommand(double time_s);

  /// Advances to `time_s`: in CAN command mode with no valid command for more than
  /// command_timeout_s, switches to the timeout mode. Returns true when that happened now.
  /// A time earlier than the last one is ignored (returns false).
  bool Step(double time_s);

  /// A fault condition was detected at `time_s`: the mode becomes fault from any mode.
  void RaiseFault(BaseFault fault, double time_s);

 private:
  // Empty when `time_s` is not before the last time seen, else the reason.
  std::string CheckTime(double time_s) const;
  std::string Refuse(ModeRequest request, const std::string& why) const;

  ModeStateMachineOptions options_;
  BaseMode mode_ = BaseMode::kStandby;
  std::uint16_t fault_bits_ = 0;
  std::uint8_t error_code_ = 0;
  double last_time_s_ = 0.0;
  double last_command_time_s_ = 0.0;
  int timeout_count_ = 0;
};

}  // namespace topay::base
