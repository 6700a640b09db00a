#include "drivers/base/base_mode.h"

namespace topay::base {

const char* ModeName(BaseMode mode) {
  switch (mode) {
    case BaseMode::kStandby: return "standby";
    case BaseMode::kCanCommand: return "CAN command";
    case BaseMode::kQuickStop: return "quick stop";
    case BaseMode::kFault: return "fault";
  }
  return "unknown mode";
}

const char* ModeRequestName(ModeRequest request) {
  switch (request) {
    case ModeRequest::kStandby: return "standby";
    case ModeRequest::kCanCommand: return "CAN command";
    case ModeRequest::kQuickStop: return "quick stop";
    case ModeRequest::kFaultReset: return "fault reset";
  }
  return "unknown request";
}

}  // namespace topay::base
