#pragma once
// The graph's status in three forms: table lines (terminal), graph_status_t (GRAPH_STATUS) and
// JSON (<run>/status.json, for scripts and tests).

#include <cstdint>
#include <string>
#include <vector>

#include "topay/graph_status_t.hpp"

namespace topay::launch {

struct ProcessStatusRow {
  std::string name;
  std::string group;
  std::int8_t state = 0;          ///< graph_status_t state constant
  std::string state_name;         ///< e.g. "RUNNING"
  int pid = 0;
  int restarts = 0;
  double cpu_percent = 0.0;
  std::int64_t rss_kB = 0;
  double heartbeat_age_s = -1.0;  ///< -1: no heartbeat yet or not monitored
  std::int8_t health = -1;        ///< heartbeat_t constant, -1: none
  std::string status;             ///< last heartbeat's status text
};

std::vector<std::string> FormatTable(const std::string& graph_name, double uptime_s,
                                     const std::vector<ProcessStatusRow>& rows);

graph_status_t ToGraphStatus(const std::string& graph_name, const std::string& run_dir,
                             std::int64_t utime, const std::vector<ProcessStatusRow>& rows);

std::string ToJson(const std::string& graph_name, const std::string& run_dir, double uptime_s,
                   const std::vector<ProcessStatusRow>& rows);

}  // namespace topay::launch
