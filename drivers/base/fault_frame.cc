#include "drivers/base/fault_frame.h"

#include <cstdio>

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

constexpr BaseFrameKind kKind = BaseFrameKind::kFault;

// Empty when the fields form a consistent report.
std::string CheckFaultFields(std::uint8_t code, std::uint8_t mode, std::uint16_t bits) {
  if (code < 1 || code > kMaxFaultCode) return "unknown fault code " + std::to_string(code);
  if (mode > kMaxBaseModeCode) return "unknown mode " + std::to_string(mode);
  if ((bits & ~kDefinedFaultBits) != 0) {
    char text[48];
    std::snprintf(text, sizeof(text), "undefined fault bits in 0x%04X",
                  static_cast<unsigned>(bits));
    return text;
  }
  if ((bits & FaultBit(static_cast<BaseFault>(code))) == 0) {
    return std::string("fault word lacks the bit of the raised fault (") + FaultCodeName(code) +
           ")";
  }
  return "";
}

}  // namespace

std::optional<can::CanFrame> EncodeFault(const FaultReport& report, int node_id,
                                         std::string* error) {
  if (const std::string bad = CheckNodeId(node_id); !bad.empty()) {
    SetError(error, std::string(FrameName(kKind)) + ": " + bad);
    return std::nullopt;
  }
  const auto code = static_cast<std::uint8_t>(report.fault);
  const auto mode = static_cast<std::uint8_t>(report.mode);
  if (std::string bad = CheckFaultFields(code, mode, report.fault_bits); !bad.empty()) {
    SetError(error, FrameLabel(kKind, node_id) + ": " + bad);
    return std::nullopt;
  }
  can::CanFrame frame = MakeEmptyFrame(kKind, node_id);
  frame.data[0] = code;
  frame.data[1] = mode;
  PutUint16Le(frame, 2, report.fault_bits);
  SealFrame(frame, report.counter);
  return frame;
}

std::optional<FaultReport> DecodeFault(const can::CanFrame& frame, int node_id,
                                       std::string* error) {
  if (std::string bad = CheckFrameShape(frame, kKind, node_id); !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  std::string bad = CheckFaultFields(frame.data[0], frame.data[1], GetUint16Le(frame, 2));
  if (bad.empty() && GetUint16Le(frame, 4) != 0) bad = "reserved bytes 4-5 are not zero";
  if (!bad.empty()) {
    SetError(error, FrameLabel(kKind, node_id) + ": " + bad);
    return std::nullopt;
  }
  FaultReport report;
  report.fault = static_cast<BaseFault>(frame.data[0]);
  report.mode = static_cast<BaseMode>(frame.data[1]);
  report.fault_bits = GetUint16Le(frame, 2);
  report.counter = frame.data[kCounterByte];
  return report;
}

}  // namespace topay::base
