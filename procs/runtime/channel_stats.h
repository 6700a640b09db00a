#pragma once
// Counters of what a process received per channel, and the rate-limited log of bad messages.

#include <cstdint>
#include <map>
#include <string>

namespace topay::procs {

struct ChannelCounts {
  std::int64_t received = 0;   ///< messages that arrived (good or bad)
  std::int64_t malformed = 0;  ///< messages CheckedDecode rejected (or the handler refused)
};

/// Per-channel counts of one process. Logs a malformed message with spdlog::warn: the first
/// kLoggedInFull of each channel in full, then one line per kLogEvery.
class ChannelStats {
 public:
  static constexpr std::int64_t kLoggedInFull = 10;
  static constexpr std::int64_t kLogEvery = 100;

  void CountGood(const std::string& channel) { ++counts_[channel].received; }
  void CountMalformed(const std::string& channel, const std::string& error);

  const ChannelCounts& Of(const std::string& channel) { return counts_[channel]; }
  std::int64_t total_malformed() const { return total_malformed_; }
  const std::map<std::string, ChannelCounts>& all() const { return counts_; }

 private:
  std::map<std::string, ChannelCounts> counts_;
  std::int64_t total_malformed_ = 0;
};

}  // namespace topay::procs
