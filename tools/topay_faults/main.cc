// topay-faults: the fault-injection suite of the whole graph (issue 22, docs/reliability.md).
// The closed-loop mission (config/graphs/demo.yaml, through CAN) runs again and again in a
// private network namespace; during each, faults are injected one after another (kill -9 of each
// process, CAN faults, LCM faults, hostile goals, hostile payloads on every channel) and the
// reaction is measured on the graph's bus: time to the safe state, recovery, other processes'
// deaths, ground-truth contacts.
//   build/bin/topay-faults --runs 20 --out out/faults            # = make faults
//   build/bin/topay-faults --faults kill-tracker,can-bus-off --runs 1
//   build/bin/topay-faults --runs 20 --out out/faults --resume   # after an interruption (Ctrl-C)
// <out>/results.md: the summary table and every episode; results.json; <out>/mission-<k>/: each
// mission's room, graph.lcmlog and process logs.

#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "fault_campaign.h"
#include "fault_results_file.h"
#include "fault_table.h"
#include "fault_verdict.h"
#include "procs/runtime/net_namespace.h"
#include "tools/common/stop_signals.h"
#include "tools/common/tool_cli.h"

namespace {

namespace fs = std::filesystem;
using namespace topay::tools;

constexpr int kExitViolations = 3;  // an episode broke a rule (contact, no stop, late stop, crash, no recovery)
constexpr int kExitInterrupted = 4;
constexpr int kExitNoNamespace = 5;  // no private network namespace could be made (nothing was run)

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> items;
  std::size_t at = 0;
  while (at <= text.size() && !text.empty()) {
    const std::size_t comma = text.find(',', at);
    const std::string item = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    if (!item.empty()) items.push_back(item);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return items;
}

bool WriteResults(const std::string& out_dir, const std::string& report, const CampaignResult& result) {
  std::ofstream md(out_dir + "/results.md");
  md << report;
  return md.good() && WriteEpisodes(out_dir + "/results.json", result.episodes);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-faults: fault injection into the closed-loop graph (kill -9, CAN, LCM, goals, hostile input)"};
  FaultCampaignOptions options;
  options.bin_dir = fs::canonical("/proc/self/exe").parent_path().string();
  options.graph_file = ConfigDir(TOPAY_CONFIG_DIR) + "/graphs/demo.yaml";
  std::string faults, seeds = "1,5,7,8";
  bool list = false, resume = false;
  app.add_option("--faults", faults, "comma-separated faults (default: every one; --list shows them)");
  app.add_option("--runs", options.runs, "episodes per fault")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--seeds", seeds, "mission room seeds, cycled")->capture_default_str();
  app.add_option("--out", options.out_dir, "results folder")->capture_default_str();
  app.add_option("--graph", options.graph_file, "the graph")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--mission-timeout-s", options.mission_timeout_s, "stop a mission's graph after this long (s)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--episodes-per-mission", options.episodes_per_mission,
                 "episodes before a mission-ending fault is injected")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--max-missions", options.max_missions, "stop after this many missions (0: 2 x faults x runs)")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  app.add_flag("--resume", resume,
               "continue the campaign in --out: its results.json's episodes count, only the runs still owed are made, "
               "new missions are numbered after the folders there");
  app.add_flag("--list", list, "list the faults and exit");
  app.footer("Exit codes: 0 every episode kept the rules, 1 file or configuration error, 2 usage error, 3 a rule was "
             "broken (results.md lists each), 4 interrupted, 5 no private network namespace (nothing run).");
  if (const std::optional<int> code = ParseCommandLine(app, argc, argv, "topay-faults")) return *code;
  try {
    options.faults = SelectFaults(SplitList(faults));
    options.seeds.clear();
    for (const std::string& s : SplitList(seeds)) options.seeds.push_back(std::stoull(s));
    if (options.seeds.empty()) throw std::invalid_argument("--seeds: no seed");
  } catch (const std::exception& e) {
    std::cerr << "topay-faults: " << e.what() << "\n";
    return kExitUsageError;
  }
  if (list) {
    for (const FaultSpec& f : options.faults) std::cout << fmt::format("{:<24} {}: {}\n", f.name, f.what, f.expected);
    return kExitSuccess;
  }
  std::string why;
  if (!topay::procs::EnterPrivateNetworkNamespace(&why)) {
    std::cerr << "topay-faults: cannot create a private network namespace (" << why << "): nothing run\n";
    return kExitNoNamespace;
  }
  options.graph_file = fs::absolute(options.graph_file).string();
  if (resume) {
    try {
      options.earlier = ReadEpisodes(options.out_dir + "/results.json");
    } catch (const std::exception& e) {
      std::cerr << "topay-faults: --resume: " << e.what() << "\n";
      return kExitFileError;
    }
    options.first_mission = NextMissionIndex(options.out_dir);
    std::cout << fmt::format("resuming: {} episodes from {}/results.json, missions from {}\n", options.earlier.size(),
                             options.out_dir, options.first_mission);
  }
  fs::create_directories(options.out_dir);
  BlockStopSignals();
  CampaignResult result;
  try {
    result = RunFaultCampaign(options, std::cout, StopRequested);
  } catch (const std::exception& e) {
    std::cerr << "topay-faults: " << e.what() << "\n";
    return kExitFileError;
  }
  const std::vector<std::string> violations = Violations(options.faults, result.episodes);
  std::string report = "# Fault injection (topay-faults)\n\n" + FaultSummaryTable(options.faults, result.episodes) +
                       "\n## Rules broken\n\n";
  for (const std::string& v : violations) report += "- " + v + "\n";
  if (violations.empty()) report += "none\n";
  report += "\n## Episodes\n\n" + EpisodeTable(result.episodes);
  std::cout << "\n" << report;
  if (!WriteResults(options.out_dir, report, result)) {
    std::cerr << "topay-faults: cannot write " << options.out_dir << "/results.{md,json}\n";
    return kExitFileError;
  }
  if (result.interrupted) return kExitInterrupted;
  return violations.empty() ? kExitSuccess : kExitViolations;
}
