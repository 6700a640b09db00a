#include "mission_runs.h"

#include <filesystem>

#include <fmt/format.h>

#include "child_command.h"
#include "log_tail.h"
#include "run_report.h"

namespace topay::tools {
namespace {

namespace fs = std::filesystem;

// The mission's log line without spdlog's "[date time] [info] " prefix.
std::string WithoutLogPrefix(const std::string& line) {
  std::size_t at = 0;
  for (int field = 0; field < 2 && at < line.size() && line[at] == '['; ++field) {
    const std::size_t end = line.find("] ", at);
    if (end == std::string::npos) break;
    at = end + 2;
  }
  return line.substr(at);
}

bool WriteScenario(const MissionRunsOptions& options, std::uint64_t seed, const std::string& run_dir,
                   std::ostream& out, MissionRunRow* row) {
  std::vector<std::string> argv = {options.bin_dir + "/topay-scenario", "--seed", std::to_string(seed), "--out",
                                   run_dir};
  if (!options.scenario_config.empty()) argv.insert(argv.end(), {"--config", options.scenario_config});
  ChildCommandOptions child;
  child.output_path = run_dir + "/scenario.out";
  const ChildCommandResult r = RunChildCommand(argv, child);
  LogTail lines(child.output_path);
  for (const std::string& line : lines.NewLines(true)) out << "  " << line << "\n";
  if (r.exit_code == 0) return true;
  row->result = "NO SCENARIO";
  row->detail = r.error.empty() ? fmt::format("topay-scenario exited with code {} (see {})", r.exit_code,
                                              child.output_path)
                                : r.error;
  return false;
}

void RunGraph(const MissionRunsOptions& options, const std::string& run_dir, std::ostream& out,
              const std::function<bool()>& stop_requested, MissionRunRow* row) {
  LogTail mission_log(run_dir + "/mission.log");
  LogTail viewer_log(run_dir + "/viz.log");
  const auto echo = [&](bool flush) {
    for (const std::string& line : mission_log.NewLines(flush)) {
      if (options.progress && line.rfind("===", 0) != 0) out << "  " << WithoutLogPrefix(line) << "\n" << std::flush;
    }
    for (const std::string& line : viewer_log.NewLines(flush)) {
      const std::size_t at = line.find("serving http://");
      if (at != std::string::npos) {
        const std::size_t url = at + 8, end = line.find(' ', url);
        out << "  viewer: " << line.substr(url, end == std::string::npos ? end : end - url) << " (open it in a browser; make demo VIEW=0 turns it off)\n"
            << std::flush;
      }
    }
  };
  ChildCommandOptions child;
  child.output_path = run_dir + "/launcher.out";
  child.timeout_s = options.timeout_s;
  child.on_poll = [&] { echo(false); };
  child.stop_requested = stop_requested;
  std::vector<std::string> command = {options.bin_dir + "/topay-launch", options.graph_file, "--run-dir", run_dir,
                                      "--plain"};
  if (!options.view) command.insert(command.end(), {"--without", "viewer"});
  const ChildCommandResult r = RunChildCommand(command, child);
  echo(true);
  if (r.timed_out) row->result = "TIMEOUT";
  if (!r.error.empty() || r.exit_code == 1 || r.exit_code == 2) {
    row->detail = r.error.empty() ? fmt::format("topay-launch exited with code {} (see {})", r.exit_code,
                                                child.output_path)
                                  : r.error;
  }
}

}  // namespace

MissionRunRow RunMissionSeed(const MissionRunsOptions& options, std::uint64_t seed, std::ostream& out,
                             const std::function<bool()>& stop_requested) {
  MissionRunRow row;
  row.seed = seed;
  row.run_dir = fs::absolute(fs::path(options.out_dir) / fmt::format("seed-{}", seed)).lexically_normal().string();
  std::error_code error;
  fs::remove_all(row.run_dir, error);
  fs::create_directories(row.run_dir, error);
  if (error) {
    row.result = "NO RUN FOLDER";
    row.detail = "cannot create " + row.run_dir + ": " + error.message();
    return row;
  }
  out << fmt::format("== seed {}: room and mission (run folder {})\n", seed, row.run_dir) << std::flush;
  if (!WriteScenario(options, seed, row.run_dir, out, &row)) return row;
  out << fmt::format("== seed {}: the closed loop (sim, director, mapper, planner, tracker, mission, logger)\n", seed)
      << std::flush;
  RunGraph(options, row.run_dir, out, stop_requested, &row);
  ReportRun(&row, out);
  return row;
}

}  // namespace topay::tools
