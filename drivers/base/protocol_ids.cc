#include "drivers/base/protocol_ids.h"

#include <array>
#include <cstdio>

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

constexpr std::array<BaseFrameKind, 6> kAllKinds = {
    BaseFrameKind::kFault,           BaseFrameKind::kModeRequest, BaseFrameKind::kStatus,
    BaseFrameKind::kVelocityCommand, BaseFrameKind::kWheelSpeeds, BaseFrameKind::kOdometry};

std::string Hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%03X", static_cast<unsigned>(value));
  return text;
}

}  // namespace

std::string CheckNodeId(int node_id) {
  if (!ValidNodeId(node_id)) {
    return "node id " + std::to_string(node_id) + " is outside 1..127";
  }
  return "";
}

std::uint32_t FrameId(BaseFrameKind kind, int node_id) {
  if (!ValidNodeId(node_id)) return 0;
  return static_cast<std::uint32_t>(kind) + static_cast<std::uint32_t>(node_id);
}

const char* FrameName(BaseFrameKind kind) {
  switch (kind) {
    case BaseFrameKind::kFault: return "fault";
    case BaseFrameKind::kModeRequest: return "mode request";
    case BaseFrameKind::kStatus: return "status";
    case BaseFrameKind::kVelocityCommand: return "velocity command";
    case BaseFrameKind::kWheelSpeeds: return "wheel speeds";
    case BaseFrameKind::kOdometry: return "odometry";
  }
  return "unknown";
}

int FrameDlc(BaseFrameKind kind) { return kind == BaseFrameKind::kModeRequest ? 2 : 8; }

std::optional<BaseFrameKind> IdentifyFrame(const can::CanFrame& frame, int node_id,
                                           std::string* error) {
  if (!ValidNodeId(node_id)) {
    SetError(error, CheckNodeId(node_id));
    return std::nullopt;
  }
  if (frame.error || frame.remote || frame.extended) {
    SetError(error, "not a base protocol frame: only standard data frames are used");
    return std::nullopt;
  }
  for (const BaseFrameKind kind : kAllKinds) {
    if (frame.id == FrameId(kind, node_id)) return kind;
  }
  // Built only when asked for: the bridge asks of every frame on the bus, most of them the drives'.
  if (error != nullptr) {
    SetError(error, "id " + Hex(frame.id) + " is not a base protocol frame of node " + std::to_string(node_id));
  }
  return std::nullopt;
}

}  // namespace topay::base
