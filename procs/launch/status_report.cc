#include "procs/launch/status_report.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace topay::launch {
namespace {

const char* HealthName(std::int8_t health) {
  switch (health) {
    case 0: return "OK";
    case 1: return "WARN";
    case 2: return "ERROR";
    default: return "-";
  }
}

}  // namespace

std::vector<std::string> FormatTable(const std::string& graph_name, double uptime_s,
                                     const std::vector<ProcessStatusRow>& rows) {
  std::vector<std::string> lines;
  char line[512];
  std::snprintf(line, sizeof(line), "graph %s, up %.0f s", graph_name.c_str(), uptime_s);
  lines.push_back(line);
  std::snprintf(line, sizeof(line), "%-20s %-9s %7s %4s %6s %8s %7s %-6s %s", "PROCESS", "STATE",
                "PID", "RST", "CPU%", "RSS_MB", "HB_AGE", "HEALTH", "STATUS");
  lines.push_back(line);
  for (const ProcessStatusRow& r : rows) {
    char age[16] = "-";
    if (r.heartbeat_age_s >= 0.0) std::snprintf(age, sizeof(age), "%.1f", r.heartbeat_age_s);
    std::snprintf(line, sizeof(line), "%-20.20s %-9s %7d %4d %6.1f %8.1f %7s %-6s %.60s",
                  r.name.c_str(), r.state_name.c_str(), r.pid, r.restarts, r.cpu_percent,
                  static_cast<double>(r.rss_kB) / 1024.0, age, HealthName(r.health),
                  r.status.c_str());
    lines.push_back(line);
  }
  return lines;
}

graph_status_t ToGraphStatus(const std::string& graph_name, const std::string& run_dir,
                             std::int64_t utime, const std::vector<ProcessStatusRow>& rows) {
  graph_status_t msg;
  msg.utime = utime;
  msg.graph_name = graph_name;
  msg.run_dir = run_dir;
  msg.num_processes = static_cast<std::int32_t>(rows.size());
  for (const ProcessStatusRow& r : rows) {
    msg.names.push_back(r.name);
    msg.states.push_back(r.state);
    msg.pids.push_back(r.pid);
    msg.restarts.push_back(r.restarts);
    msg.cpu_percent.push_back(static_cast<float>(r.cpu_percent));
    msg.rss_kB.push_back(r.rss_kB);
    msg.heartbeat_age_s.push_back(static_cast<float>(r.heartbeat_age_s));
    msg.health.push_back(r.health);
  }
  return msg;
}

std::string ToJson(const std::string& graph_name, const std::string& run_dir, double uptime_s,
                   const std::vector<ProcessStatusRow>& rows) {
  nlohmann::json json;
  json["graph"] = graph_name;
  json["run_dir"] = run_dir;
  json["uptime_s"] = uptime_s;
  json["processes"] = nlohmann::json::array();
  for (const ProcessStatusRow& r : rows) {
    json["processes"].push_back({{"name", r.name},
                                 {"group", r.group},
                                 {"state", r.state_name},
                                 {"pid", r.pid},
                                 {"restarts", r.restarts},
                                 {"cpu_percent", r.cpu_percent},
                                 {"rss_kB", r.rss_kB},
                                 {"heartbeat_age_s", r.heartbeat_age_s},
                                 {"health", r.health},
                                 {"status", r.status}});
  }
  // Heartbeat status texts come off the bus: invalid UTF-8 in one (a corrupted or hostile
  // heartbeat) is replaced, never thrown (it stopped the launcher, and the whole graph with it).
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace topay::launch
