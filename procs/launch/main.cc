// topay-launch GRAPH.yaml: starts and supervises a process graph (procs/launch/supervisor.h).
// Exit codes: 0 stopped cleanly, 1 bad graph file or start failure, 2 usage error.

#include <unistd.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "procs/launch/child_process.h"
#include "procs/launch/graph_spec.h"
#include "procs/launch/plan_text.h"
#include "procs/launch/supervisor.h"
#include "procs/runtime/net_namespace.h"
#include "procs/runtime/process_options.h"

namespace fs = std::filesystem;
using namespace topay;

namespace {

struct Flags {
  std::string graph_file;
  bool isolated = false;
  bool not_isolated = false;
  bool dry_run = false;
  bool plain = false;
  std::string run_dir;
  std::vector<std::string> groups;
  std::vector<std::string> without;
  std::optional<double> duration_s;
  std::string replay_log;
  launch::ReplayOptions replay;
};

std::string NewRunDir(const std::string& root) {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof(stamp), "%Y%m%d-%H%M%S", std::localtime(&now));
  fs::path dir = fs::path(root) / stamp;
  for (int i = 2; fs::exists(dir); ++i) dir = fs::path(root) / (std::string(stamp) + "-" + std::to_string(i));
  return dir.string();
}

void AddFlags(CLI::App& app, Flags& f) {
  app.add_option("graph", f.graph_file, "graph file (config/graphs/*.yaml)")->required();
  auto* isolated = app.add_flag("--isolated", f.isolated,
                                "run in a private network namespace (default: the graph's `isolated`)");
  app.add_flag("--no-isolated", f.not_isolated, "run in the current network namespace")->excludes(isolated);
  app.add_flag("--dry-run", f.dry_run, "print the resolved plan and exit");
  app.add_flag("--plain", f.plain, "no colours or live table even on a terminal");
  app.add_option("--run-dir", f.run_dir, "run folder (default: <run_root>/<date-time>)");
  app.add_option("--group", f.groups, "start only these groups (and their dependencies)");
  app.add_option("--without", f.without, "leave out the processes of these groups (e.g. viewer)");
  app.add_option("--duration", f.duration_s, "stop the graph after this many seconds");
  app.add_option("--replay", f.replay_log, "play this LCM log into the graph once it is ready");
  app.add_option("--speed", f.replay.speed, "replay speed factor (<= 0: as fast as possible)")->capture_default_str();
  app.add_option("--start", f.replay.start_offset_s, "replay from this offset into the log, s")->capture_default_str();
  app.add_option("--channels", f.replay.channels, "replay only channels matching this regex")->capture_default_str();
  app.add_option("--linger", f.replay.linger_s, "after the replay, stop the graph after this many s")->capture_default_str();
}

// Loads, selects and expands the graph; checks every command exists. Throws GraphError.
launch::GraphSpec Resolve(const Flags& f, const std::string& run_dir) {
  launch::GraphSpec graph = launch::LoadGraph(f.graph_file);
  launch::SelectGroups(f.groups, &graph);
  launch::ExcludeGroups(f.without, &graph);
  if (graph.processes.empty()) throw launch::GraphError(f.graph_file + ": no process in the selected groups");
  launch::GraphVariables vars;
  vars.values["BIN_DIR"] = fs::canonical("/proc/self/exe").parent_path().string();
  vars.values["GRAPH_DIR"] = fs::absolute(f.graph_file).parent_path().lexically_normal().string();
  vars.values["RUN_DIR"] = run_dir;
  launch::ExpandVariables(vars, &graph);
  for (const launch::ProcessSpec& p : graph.processes) {
    if (launch::ResolveCommand(p.command).empty()) {
      throw launch::GraphError(f.graph_file + ": process " + p.name + ".command: '" + p.command +
                               "' not found or not executable");
    }
  }
  return graph;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-launch: start and supervise a TopAY process graph"};
  Flags f;
  AddFlags(app, f);
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  launch::GraphSpec graph;
  std::string run_dir;
  try {
    const launch::GraphSpec raw = launch::LoadGraph(f.graph_file);
    run_dir = fs::absolute(f.run_dir.empty() ? NewRunDir(raw.run_root) : f.run_dir).string();
    graph = Resolve(f, run_dir);
  } catch (const launch::GraphError& e) {
    std::cerr << "topay-launch: " << e.what() << "\n";
    return procs::kExitConfigError;
  }
  const bool isolated = f.isolated || (graph.isolated && !f.not_isolated);
  if (f.dry_run) {
    std::cout << launch::DescribePlan(graph, isolated, run_dir);
    if (!f.replay_log.empty()) {
      std::cout << "  replay: " << f.replay_log << " once every process is ready, speed " << f.replay.speed
                << ", from " << f.replay.start_offset_s << " s, channels '" << f.replay.channels
                << "', leaving out HEARTBEAT, GRAPH_STATUS and the channels the processes publish\n";
    }
    return procs::kExitOk;
  }
  std::error_code error;
  fs::create_directories(run_dir, error);
  if (error) {
    std::cerr << "topay-launch: cannot create the run folder " << run_dir << ": " << error.message() << "\n";
    return procs::kExitConfigError;
  }
  if (isolated) {
    std::string why;
    if (!procs::EnterPrivateNetworkNamespace(&why)) {
      std::cerr << "topay-launch: --isolated: cannot create a private network namespace: " << why << "\n";
      return procs::kExitConfigError;
    }
  }
  launch::SupervisorOptions options;
  options.run_dir = run_dir;
  options.tty = !f.plain && isatty(STDOUT_FILENO) != 0;
  options.duration_s = f.duration_s;
  if (!f.replay_log.empty()) {
    f.replay.log_path = f.replay_log;
    options.replay = f.replay;
  }
  try {
    launch::Supervisor supervisor(std::move(graph), options);
    if (isolated) std::cout << "[topay-launch] isolated: private network namespace, loopback multicast only\n";
    return supervisor.Run();
  } catch (const std::exception& e) {
    std::cerr << "topay-launch: " << e.what() << "\n";
    return procs::kExitConfigError;
  }
}
