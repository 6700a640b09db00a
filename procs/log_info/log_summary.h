#pragma once
// What an LCM log holds, per channel: message types (by fingerprint), counts, rates, sizes, time
// span and how many messages fail to decode (topay-log-info).

#include <cstdint>
#include <map>
#include <string>

namespace topay::loginfo {

struct ChannelSummary {
  std::int64_t count = 0;
  std::int64_t bytes = 0;
  std::int64_t min_bytes = 0, max_bytes = 0;
  std::int64_t first_utime = 0, last_utime = 0;  ///< earliest and latest log timestamps, us
  std::map<std::string, std::int64_t> types;     ///< type name (or "unknown") -> count
  std::int64_t decode_failures = 0;  ///< known fingerprint but CheckedDecode failed, or unknown

  /// Messages per second over the channel's own span (0 for fewer than 2 messages).
  double rate_hz() const;
};

struct LogSummary {
  std::string path;
  std::int64_t events = 0;
  std::int64_t first_utime = 0, last_utime = 0;
  std::map<std::string, ChannelSummary> channels;

  double span_s() const { return static_cast<double>(last_utime - first_utime) * 1e-6; }
};

/// Reads the whole log. Throws std::runtime_error naming the file if it cannot be opened.
LogSummary SummarizeLog(const std::string& path);

/// A table, one line per channel, plus the totals.
std::string FormatSummary(const LogSummary& summary);
/// The same as JSON.
std::string SummaryJson(const LogSummary& summary);

}  // namespace topay::loginfo
