#pragma once
// The closed loop of the graph tests: topay-mapper, topay-planner, topay-tracker and topay-sim
// driven by the tracker's CONTROL_COMMAND (its plant with command latency and actuator lag: not
// the ideal follower), as real processes, in the room `dir`/room.json.

#include <string>
#include <vector>

#include "graph_test_support.h"

namespace topay::test {

/// Starts the closed loop in `dir` (logs mapper.txt, planner.txt, tracker.txt, sim.txt); the
/// planner gets 10 s for a plan from rest (config/planner/topay.yaml otherwise).
inline std::vector<pid_t> SpawnClosedLoopGraph(const std::string& dir, const std::string& lcm_url) {
  const auto config = [](const std::string& rel) { return std::string(TOPAY_SOURCE_DIR) + "/config/" + rel; };
  WriteText(dir + "/planner.yaml",
            "planner_config: " + config("planner/topay.yaml") + "\ntiming: {from_rest_time_limit_s: 10.0}\n");
  const auto process = [&](const std::string& name, std::vector<std::string> args) {
    args.insert(args.begin(), BinDir() + "/topay-" + name);
    for (const std::string& a : {std::string("--name"), name, std::string("--lcm-url"), lcm_url}) args.push_back(a);
    return Spawn(args, dir + "/" + name + ".txt");
  };
  return {process("mapper", {"--config", config("mapper/mapper.yaml")}),
          process("planner", {"--config", dir + "/planner.yaml"}),
          process("tracker", {"--config", config("tracker/tracker.yaml")}),
          process("sim", {"--config", config("sim/sim.yaml"), "--scene", dir + "/room.json"})};
}

}  // namespace topay::test
