#include "drivers/base/wheel_speeds_frame.h"

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

constexpr BaseFrameKind kKind = BaseFrameKind::kWheelSpeeds;
constexpr double kMradPerRad = 1000.0;

}  // namespace

std::optional<can::CanFrame> EncodeWheelSpeeds(const WheelSpeedsFeedback& speeds, int node_id,
                                               std::string* error) {
  if (const std::string bad = CheckNodeId(node_id); !bad.empty()) {
    SetError(error, std::string(FrameName(kKind)) + ": " + bad);
    return std::nullopt;
  }
  std::string why;
  const auto left = ScaleToRaw(speeds.left_rad_per_s, kMradPerRad, -kMaxWheelSpeedRaw,
                               kMaxWheelSpeedRaw, "left wheel speed [rad/s]", &why);
  const auto right = left ? ScaleToRaw(speeds.right_rad_per_s, kMradPerRad, -kMaxWheelSpeedRaw,
                                       kMaxWheelSpeedRaw, "right wheel speed [rad/s]", &why)
                          : std::nullopt;
  if (!left || !right) {
    SetError(error, FrameLabel(kKind, node_id) + ": " + why);
    return std::nullopt;
  }
  can::CanFrame frame = MakeEmptyFrame(kKind, node_id);
  PutInt16Le(frame, 0, static_cast<std::int16_t>(*left));
  PutInt16Le(frame, 2, static_cast<std::int16_t>(*right));
  SealFrame(frame, speeds.counter);
  return frame;
}

std::optional<WheelSpeedsFeedback> DecodeWheelSpeeds(const can::CanFrame& frame, int node_id,
                                                     std::string* error) {
  if (std::string bad = CheckFrameShape(frame, kKind, node_id); !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  const std::int16_t left = GetInt16Le(frame, 0);
  const std::int16_t right = GetInt16Le(frame, 2);
  std::string bad = GetUint16Le(frame, 4) != 0 ? "reserved bytes 4-5 are not zero" : "";
  if (bad.empty()) {
    bad = CheckRawRange(left, -kMaxWheelSpeedRaw, kMaxWheelSpeedRaw, "left wheel [mrad/s]");
  }
  if (bad.empty()) {
    bad = CheckRawRange(right, -kMaxWheelSpeedRaw, kMaxWheelSpeedRaw, "right wheel [mrad/s]");
  }
  if (!bad.empty()) {
    SetError(error, FrameLabel(kKind, node_id) + ": " + bad);
    return std::nullopt;
  }
  WheelSpeedsFeedback speeds;
  speeds.left_rad_per_s = left / kMradPerRad;
  speeds.right_rad_per_s = right / kMradPerRad;
  speeds.counter = frame.data[kCounterByte];
  return speeds;
}

}  // namespace topay::base
