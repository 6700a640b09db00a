#include "drivers/base/mode_state_machine.h"

#include <cmath>
#include <stdexcept>

namespace topay::base {

std::string CheckModeStateMachineOptions(const ModeStateMachineOptions& options) {
  if (!std::isfinite(options.command_timeout_s) || options.command_timeout_s <= 0.0) {
    return "command_timeout_s must be finite and > 0";
  }
  if (options.timeout_mode != BaseMode::kQuickStop && options.timeout_mode != BaseMode::kStandby) {
    return "timeout_mode must be quick stop or standby";
  }
  return "";
}

ModeStateMachine::ModeStateMachine(const ModeStateMachineOptions& options, double start_time_s)
    : options_(options), last_time_s_(start_time_s), last_command_time_s_(start_time_s) {
  if (const std::string bad = CheckModeStateMachineOptions(options); !bad.empty()) {
    throw std::invalid_argument("ModeStateMachineOptions: " + bad);
  }
}

std::string ModeStateMachine::CheckTime(double time_s) const {
  if (!std::isfinite(time_s)) return "time is not finite";
  if (time_s < last_time_s_) return "time went back";
  return "";
}

std::string ModeStateMachine::Refuse(ModeRequest request, const std::string& why) const {
  return std::string(ModeRequestName(request)) + " refused in " + ModeName(mode_) + ": " + why;
}

bool ModeStateMachine::Step(double time_s) {
  if (!CheckTime(time_s).empty()) return false;
  last_time_s_ = time_s;
  if (mode_ != BaseMode::kCanCommand) return false;
  if (time_s - last_command_time_s_ <= options_.command_timeout_s) return false;
  mode_ = options_.timeout_mode;
  ++timeout_count_;
  return true;
}

std::string ModeStateMachine::Request(ModeRequest request, double time_s) {
  if (const std::string bad = CheckTime(time_s); !bad.empty()) return Refuse(request, bad);
  Step(time_s);
  if (mode_ == BaseMode::kFault && request != ModeRequest::kFaultReset) {
    return Refuse(request, "only a fault reset leaves fault");
  }
  switch (request) {
    case ModeRequest::kStandby:
      mode_ = BaseMode::kStandby;
      return "";
    case ModeRequest::kCanCommand:
      if (mode_ == BaseMode::kQuickStop) {
        return Refuse(request, "quick stop is left through standby");
      }
      if (mode_ == BaseMode::kStandby) last_command_time_s_ = time_s;  // arm the watchdog
      mode_ = BaseMode::kCanCommand;
      return "";
    case ModeRequest::kQuickStop:
      mode_ = BaseMode::kQuickStop;
      return "";
    case ModeRequest::kFaultReset:
      if (mode_ != BaseMode::kFault) return Refuse(request, "there is no fault to reset");
      mode_ = BaseMode::kStandby;
      fault_bits_ = 0;
      error_code_ = 0;
      return "";
  }
  return Refuse(request, "unknown request");
}

std::string ModeStateMachine::AcceptVelocityCommand(double time_s) {
  if (const std::string bad = CheckTime(time_s); !bad.empty()) {
    return "velocity command ignored: " + bad;
  }
  Step(time_s);
  if (mode_ != BaseMode::kCanCommand) {
    return std::string("velocity command ignored in ") + ModeName(mode_);
  }
  last_command_time_s_ = time_s;
  return "";
}

void ModeStateMachine::RaiseFault(BaseFault fault, double time_s) {
  if (CheckTime(time_s).empty()) last_time_s_ = time_s;
  mode_ = BaseMode::kFault;
  fault_bits_ |= FaultBit(fault);
  error_code_ = static_cast<std::uint8_t>(fault);
}

}  // namespace topay::base
