#include "drivers/arm/nmt.h"

#include "drivers/arm/canopen_ids.h"

namespace topay::canopen {
namespace {

bool IsKnownCommand(std::uint8_t value) {
  return value == 0x01 || value == 0x02 || value == 0x80 || value == 0x81 || value == 0x82;
}

}  // namespace

std::string_view ToString(NmtCommand command) {
  switch (command) {
    case NmtCommand::kStartRemoteNode: return "start";
    case NmtCommand::kStopRemoteNode: return "stop";
    case NmtCommand::kEnterPreOperational: return "enter pre-operational";
    case NmtCommand::kResetNode: return "reset node";
    case NmtCommand::kResetCommunication: return "reset communication";
  }
  return "unknown NMT command";
}

std::optional<can::CanFrame> EncodeNmt(const NmtMessage& message, std::string* error) {
  const auto specifier = static_cast<std::uint8_t>(message.command);
  if (!IsKnownCommand(specifier)) {
    return Fail(error, "NMT: unknown command specifier " + std::to_string(specifier));
  }
  if (message.node_id != kNmtAllNodes && !CheckNodeId(message.node_id).empty()) {
    return Fail(error, "NMT: node id " + std::to_string(message.node_id) +
                           " is outside 0..127 (0 = all nodes)");
  }
  return can::CanFrame::Standard(0x000, {specifier, static_cast<std::uint8_t>(message.node_id)});
}

std::optional<NmtMessage> DecodeNmt(const can::CanFrame& frame, std::string* error) {
  if (!CheckCanopenFrame(frame, CanopenFunction::kNmt, 2, 2, "NMT", error)) return std::nullopt;
  if (!IsKnownCommand(frame.data[0])) {
    return Fail(error, FrameError("NMT", frame, "unknown command specifier " +
                                                   std::to_string(frame.data[0])));
  }
  if (frame.data[1] > kMaxNodeId) {
    return Fail(error, FrameError("NMT", frame, "node id " + std::to_string(frame.data[1]) +
                                                   " is outside 0..127"));
  }
  return NmtMessage{static_cast<NmtCommand>(frame.data[0]), frame.data[1]};
}

}  // namespace topay::canopen
