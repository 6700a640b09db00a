#include "drivers/arm/heartbeat.h"

#include "drivers/arm/canopen_ids.h"

namespace topay::canopen {
namespace {

bool IsKnownState(std::uint8_t value) {
  return value == 0x00 || value == 0x04 || value == 0x05 || value == 0x7F;
}

}  // namespace

std::string_view ToString(NmtState state) {
  switch (state) {
    case NmtState::kBootUp: return "boot-up";
    case NmtState::kStopped: return "stopped";
    case NmtState::kOperational: return "operational";
    case NmtState::kPreOperational: return "pre-operational";
  }
  return "unknown NMT state";
}

std::optional<can::CanFrame> EncodeHeartbeat(const Heartbeat& heartbeat, std::string* error) {
  const auto id = CobIdOf(CanopenFunction::kHeartbeat, heartbeat.node_id, error);
  if (!id) return std::nullopt;
  const auto state = static_cast<std::uint8_t>(heartbeat.state);
  if (!IsKnownState(state)) {
    return Fail(error, "heartbeat: unknown NMT state " + std::to_string(state));
  }
  return can::CanFrame::Standard(*id, {state});
}

std::optional<Heartbeat> DecodeHeartbeat(const can::CanFrame& frame, std::string* error) {
  const auto node_id =
      CheckCanopenFrame(frame, CanopenFunction::kHeartbeat, 1, 1, "heartbeat", error);
  if (!node_id) return std::nullopt;
  if (!IsKnownState(frame.data[0])) {
    return Fail(error, FrameError("heartbeat", frame,
                                  "unknown NMT state " + std::to_string(frame.data[0])));
  }
  return Heartbeat{*node_id, static_cast<NmtState>(frame.data[0])};
}

bool HeartbeatProducer::IsDue(double now_s) const {
  if (producer_time_s_ <= 0.0) return false;
  // 1 ns of slack: a caller ticking at exactly the period is not one tick late by rounding.
  constexpr double kSlack_s = 1e-9;
  return !last_sent_s_ || now_s - *last_sent_s_ >= producer_time_s_ - kSlack_s;
}

void HeartbeatConsumer::OnHeartbeat(NmtState state, double time_s) {
  last_state_ = state;
  last_time_s_ = time_s;
}

bool HeartbeatConsumer::IsLost(double now_s) const {
  if (consumer_time_s_ <= 0.0 || !last_time_s_) return false;
  return now_s - *last_time_s_ > consumer_time_s_;
}

}  // namespace topay::canopen
