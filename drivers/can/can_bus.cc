#include "drivers/can/can_bus.h"

namespace topay::can {

const char* ToString(CanResult::Code code) {
  switch (code) {
    case CanResult::Code::kOk: return "ok";
    case CanResult::Code::kTimeout: return "timeout";
    case CanResult::Code::kTxQueueFull: return "tx queue full";
    case CanResult::Code::kBusOff: return "bus-off";
    case CanResult::Code::kInterfaceDown: return "interface down";
    case CanResult::Code::kInvalidFrame: return "invalid frame";
    case CanResult::Code::kClosed: return "closed";
    case CanResult::Code::kIoError: return "i/o error";
  }
  return "unknown";
}

void ApplyErrorFrame(const CanFrame& frame, CanBusStatus* status) {
  if (!frame.error) return;
  const CanErrorReport report = DecodeCanErrorFrame(frame);
  const CanBusState next = NextBusState(status->state, report);
  if (next == CanBusState::kBusOff && status->state != CanBusState::kBusOff) ++status->bus_off_count;
  status->state = next;
  ++status->error_frames;
  status->last_error = report.description;
}

}  // namespace topay::can
