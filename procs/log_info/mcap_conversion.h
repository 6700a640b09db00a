#pragma once
// topay-log-info LOG --mcap OUT.mcap: an LCM log converted for Foxglove's offline player, with
// the live viewer's channels (docs/viewer.md): every message through the viewer's pipeline at
// full rate (no browser rate limits), each channel JSON with its JSON schema, stamped with the
// message's log time.

#include <cstdint>
#include <map>
#include <string>

namespace topay::loginfo {

struct McapConversionOptions {
  std::string robot_urdf;  ///< the robot the log is of (the viewer's links; "" = the shipped one)
  std::string robot_yaml;
};

/// What the conversion wrote.
struct McapConversionSummary {
  std::int64_t events = 0;       ///< LCM events read
  std::int64_t messages = 0;     ///< MCAP messages written
  std::int64_t malformed = 0;    ///< LCM messages of a known channel that failed to decode
  std::map<std::string, std::int64_t> per_topic;  ///< MCAP messages by topic
  std::string Report() const;
};

/// Converts `log_path` into `mcap_path`. Throws std::runtime_error (naming the file) if the log
/// cannot be read or the MCAP file cannot be written, ConfigError for bad robot files.
McapConversionSummary ConvertLogToMcap(const std::string& log_path, const std::string& mcap_path,
                                       const McapConversionOptions& options);

}  // namespace topay::loginfo
