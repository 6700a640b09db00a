// topay-log-info LOG: channels, types, counts, rates, sizes, time span and decode failures of an
// LCM log. Exit codes: 0, 1 unreadable log, 2 usage error.

#include <CLI/CLI.hpp>

#include <iostream>

#include "procs/log_info/log_summary.h"
#include "procs/runtime/process_options.h"

int main(int argc, char** argv) {
  CLI::App app{"topay-log-info: what an LCM log holds, per channel"};
  std::string path;
  bool json = false;
  app.add_option("log", path, "LCM log file (lcm-logger)")->required();
  app.add_flag("--json", json, "print JSON instead of a table");
  if (const std::optional<int> code = topay::procs::ParseFlags(&app, argc, argv)) return *code;
  try {
    const topay::loginfo::LogSummary summary = topay::loginfo::SummarizeLog(path);
    std::cout << (json ? topay::loginfo::SummaryJson(summary) : topay::loginfo::FormatSummary(summary));
  } catch (const std::exception& e) {
    std::cerr << "topay-log-info: " << e.what() << "\n";
    return topay::procs::kExitConfigError;
  }
  return topay::procs::kExitOk;
}
