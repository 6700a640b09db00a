#include "drivers/base/frame_bytes.h"

#include "drivers/can/little_endian.h"

#include <cmath>
#include <cstdio>

namespace topay::base {

void PutUint16Le(can::CanFrame& frame, int offset, std::uint16_t value) {
  can::PutLittleEndian(value, 2, offset, &frame.data);
}

void PutInt16Le(can::CanFrame& frame, int offset, std::int16_t value) {
  PutUint16Le(frame, offset, static_cast<std::uint16_t>(value));  // two's complement
}

void PutUint24Le(can::CanFrame& frame, int offset, std::uint32_t value) {
  can::PutLittleEndian(value, 3, offset, &frame.data);
}

std::uint16_t GetUint16Le(const can::CanFrame& frame, int offset) {
  return static_cast<std::uint16_t>(can::GetLittleEndian(frame.data, 2, offset));
}

std::int16_t GetInt16Le(const can::CanFrame& frame, int offset) {
  return static_cast<std::int16_t>(GetUint16Le(frame, offset));
}

std::uint32_t GetUint24Le(const can::CanFrame& frame, int offset) {
  return can::GetLittleEndian(frame.data, 3, offset);
}

std::uint8_t ComputeChecksum(const can::CanFrame& frame) {
  unsigned sum = (frame.id & 0xFF) + ((frame.id >> 8) & 0xFF);
  for (int i = 0; i < kChecksumByte; ++i) sum += frame.data[i];
  return static_cast<std::uint8_t>(0xFF - (sum & 0xFF));
}

can::CanFrame MakeEmptyFrame(BaseFrameKind kind, int node_id) {
  can::CanFrame frame;
  frame.id = FrameId(kind, node_id);
  frame.dlc = static_cast<std::uint8_t>(FrameDlc(kind));
  return frame;
}

void SealFrame(can::CanFrame& frame, std::uint8_t counter) {
  frame.data[kCounterByte] = counter;
  frame.data[kChecksumByte] = ComputeChecksum(frame);
}

std::string FrameLabel(BaseFrameKind kind, int node_id) {
  char id[16];
  std::snprintf(id, sizeof(id), "0x%03X", static_cast<unsigned>(FrameId(kind, node_id)));
  return std::string(FrameName(kind)) + " (" + id + ")";
}

std::string CheckFrameShape(const can::CanFrame& frame, BaseFrameKind kind, int node_id) {
  if (!ValidNodeId(node_id)) return std::string(FrameName(kind)) + ": " + CheckNodeId(node_id);
  // The label is formatted only for a frame that fails (every frame decoded asks).
  const auto label = [&] { return FrameLabel(kind, node_id); };
  if (frame.error || frame.remote || frame.extended) {
    return label() + ": not a standard data frame";
  }
  if (frame.id != FrameId(kind, node_id)) {
    char id[16];
    std::snprintf(id, sizeof(id), "0x%03X", static_cast<unsigned>(frame.id));
    return label() + ": wrong id " + id;
  }
  const int expected_dlc = FrameDlc(kind);
  if (frame.dlc != expected_dlc) {
    return label() + ": DLC " + std::to_string(frame.dlc) + ", expected " + std::to_string(expected_dlc);
  }
  if (expected_dlc == 8 && frame.data[kChecksumByte] != ComputeChecksum(frame)) {
    return label() + ": bad checksum " + std::to_string(frame.data[kChecksumByte]) + ", expected " +
           std::to_string(ComputeChecksum(frame));
  }
  return "";
}

std::optional<std::int32_t> ScaleToRaw(double value, double units_per_si, std::int32_t min_raw,
                                       std::int32_t max_raw, std::string_view field,
                                       std::string* error) {
  if (!std::isfinite(value)) {
    SetError(error, std::string(field) + " is not finite");
    return std::nullopt;
  }
  // Compare before converting to an integer: a huge value must not overflow the conversion.
  const double rounded = std::round(value * units_per_si);
  if (rounded < min_raw || rounded > max_raw) {
    char text[160];
    std::snprintf(text, sizeof(text), "%.*s %g is outside %g..%g", static_cast<int>(field.size()),
                  field.data(), value, min_raw / units_per_si, max_raw / units_per_si);
    SetError(error, text);
    return std::nullopt;
  }
  return static_cast<std::int32_t>(rounded);
}

std::string CheckRawRange(std::int32_t raw, std::int32_t min_raw, std::int32_t max_raw,
                          std::string_view field) {
  if (raw >= min_raw && raw <= max_raw) return "";
  return std::string(field) + " " + std::to_string(raw) + " is outside " +
         std::to_string(min_raw) + ".." + std::to_string(max_raw);
}

std::string CheckRollingCounter(std::string_view frame_name, std::optional<std::uint8_t> last,
                                std::uint8_t current) {
  if (!last.has_value() || *last != current) return "";
  return std::string(frame_name) + ": counter " + std::to_string(current) +
         " repeated (stale frame)";
}

int CounterGap(std::uint8_t last, std::uint8_t current) {
  return static_cast<std::uint8_t>(current - last - 1);
}

void SetError(std::string* error, std::string message) {
  if (error != nullptr) *error = std::move(message);
}

}  // namespace topay::base
