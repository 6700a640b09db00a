#include "drivers/base/odometry_frame.h"

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

constexpr BaseFrameKind kKind = BaseFrameKind::kOdometry;

}  // namespace

std::optional<can::CanFrame> EncodeOdometry(const OdometryFeedback& odometry, int node_id,
                                            std::string* error) {
  if (const std::string bad = CheckNodeId(node_id); !bad.empty()) {
    SetError(error, std::string(FrameName(kKind)) + ": " + bad);
    return std::nullopt;
  }
  can::CanFrame frame = MakeEmptyFrame(kKind, node_id);
  PutUint24Le(frame, 0, odometry.left_ticks % kTickCountModulus);
  PutUint24Le(frame, 3, odometry.right_ticks % kTickCountModulus);
  SealFrame(frame, odometry.counter);
  return frame;
}

std::optional<OdometryFeedback> DecodeOdometry(const can::CanFrame& frame, int node_id,
                                               std::optional<std::uint8_t> last_counter,
                                               std::string* error) {
  if (std::string bad = CheckFrameShape(frame, kKind, node_id); !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  if (std::string bad = CheckRollingCounter(FrameLabel(kKind, node_id), last_counter,
                                            frame.data[kCounterByte]);
      !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  OdometryFeedback odometry;
  odometry.left_ticks = GetUint24Le(frame, 0);
  odometry.right_ticks = GetUint24Le(frame, 3);
  odometry.counter = frame.data[kCounterByte];
  return odometry;
}

std::int32_t WheelTickDelta(std::uint32_t last_ticks, std::uint32_t current_ticks) {
  const std::uint32_t forward = (current_ticks - last_ticks) % kTickCountModulus;
  const auto half = static_cast<std::int32_t>(kTickCountModulus / 2);
  const auto delta = static_cast<std::int32_t>(forward);
  return delta >= half ? delta - static_cast<std::int32_t>(kTickCountModulus) : delta;
}

}  // namespace topay::base
