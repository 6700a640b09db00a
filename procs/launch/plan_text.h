#pragma once
// The resolved plan of a graph as text (topay-launch --dry-run).

#include <string>

#include "procs/launch/graph_spec.h"

namespace topay::launch {

/// Every process in start order with its resolved command line, environment, working
/// directory, dependencies, restart and heartbeat settings, real-time settings and log file.
std::string DescribePlan(const GraphSpec& graph, bool isolated, const std::string& run_dir);

}  // namespace topay::launch
