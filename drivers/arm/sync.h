#pragma once
// SYNC (CiA 301 §7.2.5): COB-ID 0x080, DLC 0, or DLC 1 with a counter 1..240 when the producer's
// synchronous counter overflow value (object 0x1019) is set.

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::canopen {

inline constexpr int kMinSyncCounter = 1;    ///< CiA 301 §7.2.5.2.1: the counter runs 1..240.
inline constexpr int kMaxSyncCounter = 240;

struct SyncMessage {
  std::optional<int> counter;  ///< Absent: DLC 0 (this robot's default, 0x1019 = 0).
};

/// The SYNC frame; nullopt with *error for a counter outside 1..240.
std::optional<can::CanFrame> EncodeSync(const SyncMessage& message, std::string* error);

/// nullopt with *error naming the frame for another id, DLC above 1 or a counter outside 1..240.
std::optional<SyncMessage> DecodeSync(const can::CanFrame& frame, std::string* error);

/// The counter after `counter` (1..240, wrapping 240 -> 1).
int NextSyncCounter(int counter);

}  // namespace topay::canopen
