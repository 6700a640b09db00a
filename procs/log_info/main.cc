// topay-log-info LOG: channels, types, counts, rates, sizes, time span and decode failures of an
// LCM log; with --mcap OUT.mcap, the log converted for Foxglove's offline player (the viewer's
// channels, docs/viewer.md). Exit codes: 0, 1 unreadable log or unwritable output, 2 usage error.

#include <CLI/CLI.hpp>

#include <iostream>

#include "procs/log_info/log_summary.h"
#include "procs/log_info/mcap_conversion.h"
#include "procs/runtime/process_options.h"

int main(int argc, char** argv) {
  CLI::App app{"topay-log-info: what an LCM log holds, per channel"};
  std::string path;
  bool json = false;
  app.add_option("log", path, "LCM log file (lcm-logger)")->required();
  app.add_flag("--json", json, "print JSON instead of a table");
  std::string mcap;
  topay::loginfo::McapConversionOptions mcap_options;
  app.add_option("--mcap", mcap, "convert the log to this MCAP file (the viewer's channels, for Foxglove)");
  app.add_option("--robot-urdf", mcap_options.robot_urdf, "--mcap: the robot's URDF (default: the shipped one)");
  app.add_option("--robot-yaml", mcap_options.robot_yaml, "--mcap: the robot's YAML (default: the shipped one)");
  if (const std::optional<int> code = topay::procs::ParseFlags(&app, argc, argv)) return *code;
  try {
    if (!mcap.empty()) {
      topay::procs::DefaultRobotFiles(topay::procs::ConfigDir(TOPAY_CONFIG_DIR), &mcap_options.robot_urdf,
                                      &mcap_options.robot_yaml);
      std::cout << "topay-log-info: " << path << " -> " << mcap << ": "
                << topay::loginfo::ConvertLogToMcap(path, mcap, mcap_options).Report();
      return topay::procs::kExitOk;
    }
    const topay::loginfo::LogSummary summary = topay::loginfo::SummarizeLog(path);
    std::cout << (json ? topay::loginfo::SummaryJson(summary) : topay::loginfo::FormatSummary(summary));
  } catch (const std::exception& e) {
    std::cerr << "topay-log-info: " << e.what() << "\n";
    return topay::procs::kExitConfigError;
  }
  return topay::procs::kExitOk;
}
