// topay-missions: the closed-loop pick-and-place mission (config/graphs/demo.yaml) over N seeds of
// room and events, one graph after another, with a table of results. `make demo` runs one seed.
//   build/bin/topay-missions --seeds 20 --first-seed 1 --out out/missions
// Per seed: <out>/seed-<S>/ holds the room, the mission, graph.lcmlog, every process's log,
// summary.json, path.png and time_plots.png; <out>/results.{md,json} the table.

#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "mission_runs.h"
#include "tools/common/stop_signals.h"
#include "tools/common/tool_cli.h"

namespace {

namespace fs = std::filesystem;
using topay::tools::MissionRunRow;

constexpr int kExitMissionFailed = 3;  // a mission failed, timed out or touched something
constexpr int kExitInterrupted = 4;    // Ctrl-C / SIGTERM: the graph was stopped

bool WriteResults(const std::string& out_dir, const std::vector<MissionRunRow>& rows, const std::string& table) {
  nlohmann::json runs = nlohmann::json::array();
  for (const MissionRunRow& r : rows) runs.push_back(topay::tools::ToJson(r));
  std::ofstream md(out_dir + "/results.md"), json(out_dir + "/results.json");
  md << table;
  json << nlohmann::json{{"runs", runs}}.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";  // texts off the bus
  return md.good() && json.good();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-missions: the closed-loop pick-and-place mission over N seeds, one graph after another"};
  topay::tools::MissionRunsOptions options;
  const std::string exe_dir = fs::canonical("/proc/self/exe").parent_path().string();
  options.bin_dir = exe_dir;
  options.graph_file = topay::tools::ConfigDir(TOPAY_CONFIG_DIR) + "/graphs/demo.yaml";
  bool quiet = false;
  app.add_option("--seeds", options.seeds, "how many seeds")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--first-seed", options.first_seed, "the first seed (room, goals, events)")
      ->check(topay::tools::NonNegativeInteger())->capture_default_str();
  app.add_option("--out", options.out_dir, "results folder (run folders <out>/seed-<S>)")->capture_default_str();
  app.add_option("--graph", options.graph_file, "the graph to run")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--scenario-config", options.scenario_config, "topay-scenario's options (YAML)")
      ->check(CLI::ExistingFile);
  app.add_option("--timeout-s", options.timeout_s, "stop a graph after this long (s)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app.add_flag("--quiet", quiet, "no progress lines (the summaries and the table only)");
  bool no_view = false;
  app.add_flag("--no-view", no_view, "leave out the graph's viewer (topay-viz, group viewer)");
  app.footer("Exit codes: 0 every mission that ran succeeded without contact, 1 file or configuration error (or "
             "no seed had a scenario), 2 usage error, 3 a mission failed, timed out or touched something, 4 "
             "interrupted. A seed whose room has no pick-and-place scenario is listed, not run.");
  if (const std::optional<int> code = topay::tools::ParseCommandLine(app, argc, argv, "topay-missions")) return *code;
  options.view = !no_view;
  options.progress = !quiet;
  options.graph_file = fs::absolute(options.graph_file).string();
  std::error_code error;
  fs::create_directories(options.out_dir, error);
  if (error) {
    std::cerr << "topay-missions: cannot create " << options.out_dir << ": " << error.message() << "\n";
    return topay::tools::kExitFileError;
  }
  topay::tools::BlockStopSignals();
  bool interrupted = false;
  const auto stop = [&] { return interrupted = interrupted || topay::tools::StopRequested(); };
  std::vector<MissionRunRow> rows;
  for (int k = 0; k < options.seeds && !stop(); ++k) {
    rows.push_back(topay::tools::RunMissionSeed(options, options.first_seed + k, std::cout, stop));
  }
  const std::string table = topay::tools::ResultsTable(rows);
  std::cout << "\n" << table;
  if (!WriteResults(options.out_dir, rows, table)) {
    std::cerr << "topay-missions: cannot write " << options.out_dir << "/results.{md,json}\n";
    return topay::tools::kExitFileError;
  }
  std::cout << "results: " << options.out_dir << "/results.md, results.json\n";
  if (interrupted) return kExitInterrupted;
  const bool none_ran = std::all_of(rows.begin(), rows.end(), [](const MissionRunRow& r) { return r.NoScenario(); });
  if (none_ran) {
    std::cerr << "topay-missions: no seed had a pick-and-place scenario (try other seeds)\n";
    return topay::tools::kExitFileError;
  }
  const bool all = std::all_of(rows.begin(), rows.end(), [](const MissionRunRow& r) { return r.Success() || r.NoScenario(); });
  return all ? topay::tools::kExitSuccess : kExitMissionFailed;
}
