#include "drivers/arm/sync.h"

#include "drivers/arm/canopen_ids.h"

namespace topay::canopen {

std::optional<can::CanFrame> EncodeSync(const SyncMessage& message, std::string* error) {
  if (!message.counter) return can::CanFrame::Standard(0x080);
  const int counter = *message.counter;
  if (counter < kMinSyncCounter || counter > kMaxSyncCounter) {
    return Fail(error, "SYNC: counter " + std::to_string(counter) + " is outside 1..240");
  }
  return can::CanFrame::Standard(0x080, {static_cast<std::uint8_t>(counter)});
}

std::optional<SyncMessage> DecodeSync(const can::CanFrame& frame, std::string* error) {
  if (!CheckCanopenFrame(frame, CanopenFunction::kSync, 0, 1, "SYNC", error)) {
    return std::nullopt;
  }
  if (frame.dlc == 0) return SyncMessage{};
  const int counter = frame.data[0];
  if (counter < kMinSyncCounter || counter > kMaxSyncCounter) {
    return Fail(error, FrameError("SYNC", frame,
                                  "counter " + std::to_string(counter) + " is outside 1..240"));
  }
  return SyncMessage{counter};
}

int NextSyncCounter(int counter) { return counter >= kMaxSyncCounter ? 1 : counter + 1; }

}  // namespace topay::canopen
