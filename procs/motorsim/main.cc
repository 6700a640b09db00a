// topay-motorsim: the motor-controller simulator (docs/motorsim.md). The base's wheel controller
// and the arm's seven CiA 402 drives as nodes on a CAN bus (--can URL), driven by the plant state
// topay-sim publishes in CAN mode (SIM_PLANT_STATE), driving it back with ACTUATOR_COMMAND at
// 200 Hz; faults injected from the config and MOTORSIM_FAULT. Exit codes: 0, 1 config or bus
// error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>

#include "core/common/error.h"
#include "drivers/can/can_url.h"
#include "procs/motorsim/motorsim_node.h"
#include "procs/runtime/process_loop.h"
#include "sim/motors/motorsim_options.h"

using namespace topay;

int main(int argc, char** argv) {
  CLI::App app{"topay-motorsim: the simulated wheel controller and arm drives on a CAN bus"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-motorsim", &process);
  std::string can_url = "udp://239.255.1.1:9000";
  app.add_option("--can", can_url,
                 "the CAN bus: udp://GROUP:PORT (the user-space bus; only in a private network namespace) or "
                 "socketcan://IFACE (default udp://239.255.1.1:9000, the sim graph's)");
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  sim::motors::MotorSimOptions options;
  try {
    if (!process.config_path.empty()) options = sim::motors::LoadMotorSimOptions(process.config_path);
  } catch (const ConfigError& e) {
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  std::string error;
  std::unique_ptr<can::CanBus> bus = can::OpenCanBus(can_url, can::CanBusOptions{}, &error);
  if (!bus) {
    spdlog::error("cannot open the CAN bus: {}", error);
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  sim::motors::MotorSim sim(options, 0.0);
  motorsim::MotorSimNodeOptions node_options;
  node_options.step_period_s = options.step_period_s;
  node_options.stalled_plant = options.stalled_plant;
  motorsim::MotorSimNode node(&loop, bus.get(), &sim, node_options);
  spdlog::info("{}: bus {}, base node {}, {} drives (nodes {}..{}), step {} ms, {} scripted faults", process.name,
               bus->url(), options.base.node_id, sim.num_joints(), options.joint_node_ids.front(),
               options.joint_node_ids.back(), options.step_period_s * 1e3, options.faults.events.size());
  const int code = loop.Run();
  std::printf("%s\n", node.FinalReport().c_str());
  std::fflush(stdout);
  return code;
}
