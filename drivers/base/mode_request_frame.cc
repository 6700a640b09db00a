#include "drivers/base/mode_request_frame.h"

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

constexpr BaseFrameKind kKind = BaseFrameKind::kModeRequest;

}  // namespace

std::optional<can::CanFrame> EncodeModeRequest(ModeRequest request, int node_id,
                                               std::string* error) {
  if (const std::string bad = CheckNodeId(node_id); !bad.empty()) {
    SetError(error, std::string(FrameName(kKind)) + ": " + bad);
    return std::nullopt;
  }
  const auto code = static_cast<std::uint8_t>(request);
  if (code > kMaxModeRequestCode) {
    SetError(error, FrameLabel(kKind, node_id) + ": unknown request code " +
                        std::to_string(code));
    return std::nullopt;
  }
  can::CanFrame frame = MakeEmptyFrame(kKind, node_id);
  frame.data[0] = code;
  frame.data[1] = static_cast<std::uint8_t>(0xFF - code);
  return frame;
}

std::optional<ModeRequest> DecodeModeRequest(const can::CanFrame& frame, int node_id,
                                             std::string* error) {
  if (std::string bad = CheckFrameShape(frame, kKind, node_id); !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  const std::string label = FrameLabel(kKind, node_id);
  const std::uint8_t code = frame.data[0];
  if (frame.data[1] != 0xFF - code) {
    SetError(error, label + ": byte 1 (" + std::to_string(frame.data[1]) +
                        ") is not the complement of the request code " + std::to_string(code));
    return std::nullopt;
  }
  if (code > kMaxModeRequestCode) {
    SetError(error, label + ": unknown request code " + std::to_string(code));
    return std::nullopt;
  }
  return static_cast<ModeRequest>(code);
}

}  // namespace topay::base
