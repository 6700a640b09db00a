#pragma once
// topay-missions' work: for each seed, the closed-loop mission in a room of that seed, one graph
// after another. Per seed: topay-scenario writes the room and the mission into the run folder,
// topay-launch runs the demo graph there (isolated; the mission ends it), the mission's log is
// echoed as progress, and topay-report's library makes the summary and the plots.

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

#include "results_table.h"

namespace topay::tools {

struct MissionRunsOptions {
  std::uint64_t first_seed = 1;   ///< the first room and events seed
  int seeds = 1;                  ///< how many seeds, one after another
  std::string out_dir = "out/missions";  ///< run folders are <out_dir>/seed-<S>/ (emptied first)
  std::string graph_file;         ///< the graph (config/graphs/demo.yaml)
  std::string bin_dir;            ///< where topay-launch and topay-scenario are
  std::string scenario_config;    ///< topay-scenario's --config (empty: its default)
  double timeout_s = 900.0;       ///< a graph still running after this long is stopped (TIMEOUT)
  bool progress = true;           ///< echo the mission's log lines while it runs
  /// Run the graph's viewer (its group "viewer": topay-viz) and print its address once it
  /// serves; false: topay-launch --without viewer.
  bool view = true;
};

/// Runs the mission of `seed` and reports it (summary text on `out`; summary.json, path.png and
/// time_plots.png in the run folder). `stop_requested` is polled: true stops the graph (the
/// row's result is then ABORTED, or whatever the mission reported).
MissionRunRow RunMissionSeed(const MissionRunsOptions& options, std::uint64_t seed, std::ostream& out,
                             const std::function<bool()>& stop_requested);

}  // namespace topay::tools
