#include "procs/log_info/log_summary.h"

#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "procs/msgs/type_registry.h"

namespace topay::loginfo {

double ChannelSummary::rate_hz() const {
  if (count < 2 || last_utime <= first_utime) return 0.0;
  return static_cast<double>(count - 1) / (static_cast<double>(last_utime - first_utime) * 1e-6);
}

LogSummary SummarizeLog(const std::string& path) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error(path + ": cannot open the LCM log");
  LogSummary summary;
  summary.path = path;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    ChannelSummary& c = summary.channels[event->channel];
    const std::int64_t size = event->datalen;
    if (c.count == 0) {
      c.first_utime = event->timestamp;
      c.min_bytes = c.max_bytes = size;
    }
    ++c.count;
    c.bytes += size;
    c.min_bytes = std::min(c.min_bytes, size);
    c.max_bytes = std::max(c.max_bytes, size);
    c.first_utime = std::min(c.first_utime, event->timestamp);  // robust to out-of-order logs
    c.last_utime = std::max(c.last_utime, event->timestamp);
    const std::optional<msgs::MessageTypeInfo> type = msgs::IdentifyMessage(event->data, size);
    std::string error;
    if (std::string(event->channel).starts_with("LCM_SELF_TEST")) {
      ++c.types["lcm-self-test"];  // LCM's own start-up probe, not a topay message
    } else if (!type) {
      ++c.types["unknown"];
      ++c.decode_failures;
    } else {
      ++c.types[type->name];
      if (!type->check(event->data, size, &error)) ++c.decode_failures;
    }
    summary.first_utime = summary.events == 0 ? event->timestamp : std::min(summary.first_utime, event->timestamp);
    summary.last_utime = summary.events == 0 ? event->timestamp : std::max(summary.last_utime, event->timestamp);
    ++summary.events;
  }
  return summary;
}

std::string FormatSummary(const LogSummary& s) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof(line), "%s: %lld messages on %zu channels over %.3f s\n", s.path.c_str(),
                static_cast<long long>(s.events), s.channels.size(), s.span_s());
  out += line;
  std::snprintf(line, sizeof(line), "%-20s %-22s %8s %9s %10s %10s %10s %9s\n", "CHANNEL", "TYPE", "COUNT",
                "RATE_HZ", "MEAN_B", "MAX_B", "SPAN_S", "BAD");
  out += line;
  for (const auto& [channel, c] : s.channels) {
    std::string types;
    for (const auto& [name, count] : c.types) {
      types += (types.empty() ? "" : ",") + name + (c.types.size() > 1 ? "(" + std::to_string(count) + ")" : "");
    }
    std::snprintf(line, sizeof(line), "%-20s %-22s %8lld %9.2f %10.0f %10lld %10.3f %9lld\n", channel.c_str(),
                  types.c_str(), static_cast<long long>(c.count), c.rate_hz(),
                  static_cast<double>(c.bytes) / static_cast<double>(c.count), static_cast<long long>(c.max_bytes),
                  static_cast<double>(c.last_utime - c.first_utime) * 1e-6, static_cast<long long>(c.decode_failures));
    out += line;
  }
  return out;
}

std::string SummaryJson(const LogSummary& s) {
  nlohmann::json json;
  json["path"] = s.path;
  json["events"] = s.events;
  json["span_s"] = s.span_s();
  json["first_utime"] = s.first_utime;
  json["last_utime"] = s.last_utime;
  for (const auto& [channel, c] : s.channels) {
    json["channels"][channel] = {{"count", c.count},           {"bytes", c.bytes},
                                 {"min_bytes", c.min_bytes},   {"max_bytes", c.max_bytes},
                                 {"rate_hz", c.rate_hz()},     {"first_utime", c.first_utime},
                                 {"last_utime", c.last_utime}, {"types", c.types},
                                 {"decode_failures", c.decode_failures}};
  }
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";  // channel names from the log
}

}  // namespace topay::loginfo
