#include "procs/runtime/channel_stats.h"

#include <spdlog/spdlog.h>

namespace topay::procs {

void ChannelStats::CountMalformed(const std::string& channel, const std::string& error) {
  ChannelCounts& counts = counts_[channel];
  ++counts.received;
  ++counts.malformed;
  ++total_malformed_;
  if (counts.malformed <= kLoggedInFull || counts.malformed % kLogEvery == 0) {
    spdlog::warn("dropped malformed message #{} on {}: {}", counts.malformed, channel, error);
  }
}

}  // namespace topay::procs
