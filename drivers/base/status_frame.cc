#include "drivers/base/status_frame.h"

#include <cstdio>

#include "drivers/base/fault_codes.h"
#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

constexpr BaseFrameKind kKind = BaseFrameKind::kStatus;
constexpr double kRawPerVolt = 100.0;  // 10 mV units

// Empty when mode, error code and fault bits are all defined values.
std::string CheckStatusFields(std::uint8_t mode, std::uint8_t error_code, std::uint16_t bits) {
  if (mode > kMaxBaseModeCode) return "unknown mode " + std::to_string(mode);
  if (error_code > kMaxFaultCode) return "unknown error code " + std::to_string(error_code);
  if ((bits & ~kDefinedFaultBits) != 0) {
    return "undefined fault bits in 0x" + [&] {
      char text[8];
      std::snprintf(text, sizeof(text), "%04X", static_cast<unsigned>(bits));
      return std::string(text);
    }();
  }
  return "";
}

}  // namespace

std::optional<can::CanFrame> EncodeStatus(const BaseStatus& status, int node_id,
                                          std::string* error) {
  if (const std::string bad = CheckNodeId(node_id); !bad.empty()) {
    SetError(error, std::string(FrameName(kKind)) + ": " + bad);
    return std::nullopt;
  }
  const std::string label = FrameLabel(kKind, node_id);
  const auto mode = static_cast<std::uint8_t>(status.mode);
  if (std::string bad = CheckStatusFields(mode, status.error_code, status.fault_bits);
      !bad.empty()) {
    SetError(error, label + ": " + bad);
    return std::nullopt;
  }
  std::string why;
  const auto battery = ScaleToRaw(status.battery_voltage_v, kRawPerVolt, 0, kMaxBatteryVoltageRaw,
                                  "battery voltage [V]", &why);
  if (!battery) {
    SetError(error, label + ": " + why);
    return std::nullopt;
  }
  can::CanFrame frame = MakeEmptyFrame(kKind, node_id);
  frame.data[0] = mode;
  frame.data[1] = status.error_code;
  PutUint16Le(frame, 2, status.fault_bits);
  PutUint16Le(frame, 4, static_cast<std::uint16_t>(*battery));
  SealFrame(frame, status.counter);
  return frame;
}

std::optional<BaseStatus> DecodeStatus(const can::CanFrame& frame, int node_id,
                                       std::string* error) {
  if (std::string bad = CheckFrameShape(frame, kKind, node_id); !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  const std::uint16_t battery = GetUint16Le(frame, 4);
  std::string bad = CheckStatusFields(frame.data[0], frame.data[1], GetUint16Le(frame, 2));
  if (bad.empty()) bad = CheckRawRange(battery, 0, kMaxBatteryVoltageRaw, "battery [10 mV]");
  if (!bad.empty()) {
    SetError(error, FrameLabel(kKind, node_id) + ": " + bad);
    return std::nullopt;
  }
  BaseStatus status;
  status.mode = static_cast<BaseMode>(frame.data[0]);
  status.error_code = frame.data[1];
  status.fault_bits = GetUint16Le(frame, 2);
  status.battery_voltage_v = battery / kRawPerVolt;
  status.counter = frame.data[kCounterByte];
  return status;
}

}  // namespace topay::base
