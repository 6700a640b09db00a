#include "procs/canbridge/frame_counters.h"

#include <spdlog/spdlog.h>

namespace topay::canbridge {

void FrameCounters::Count(const std::string& key, const std::string& message) {
  std::int64_t& count = by_kind_[key];
  if (count++ == 0) {
    last_message_ = message;
    spdlog::warn("{} (logged once for this kind; counted in DRIVE_STATUS)", message);
  }
}

void FrameCounters::CountMalformed(const std::string& kind, const std::string& error) {
  ++malformed_;
  Count("malformed: " + kind, "malformed frame, " + kind + ": " + error);
}

void FrameCounters::CountUnknown(const std::string& kind, const std::string& text) {
  ++unknown_;
  Count("unknown: " + kind, "unknown frame " + text);
}

}  // namespace topay::canbridge
