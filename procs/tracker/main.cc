// topay-tracker: the NMPC trajectory tracker of the graph (docs/tracker.md). TRAJECTORY,
// ROBOT_STATE, GRIPPER_COMMAND, DRIVE_STATUS and the planner's HEARTBEAT in; CONTROL_COMMAND and
// TRACKER_STATUS out at 50 Hz; POINT_CLOUD in for the protective field. Stops within the robot's
// acceleration limits without a trajectory, after its end, when the robot state is stale or
// jumps, when the planner restarted or fell silent, or when the LiDAR shows an obstacle on the
// base's path ahead (the protective field). Exit codes: 0, 1 config or file error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "core/control/tracker_limits.h"
#include "core/io/robot_loader.h"
#include "procs/runtime/process_loop.h"
#include "procs/tracker/tracker_node.h"
#include "procs/tracker/tracker_options.h"

using namespace topay;
using namespace topay::tracker;

namespace {

TrackerOptions ResolveOptions(const procs::ProcessOptions& process) {
  TrackerOptions o = process.config_path.empty() ? TrackerOptions{} : LoadTrackerOptions(process.config_path);
  const std::string config_dir = procs::ConfigDir(TOPAY_CONFIG_DIR);
  procs::DefaultRobotFiles(config_dir, &o.robot_urdf, &o.robot_yaml);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-tracker: NMPC trajectory tracking at 50 Hz, safe stop"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-tracker", &process);
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  TrackerOptions options;
  std::unique_ptr<TrackerNode> node;
  try {
    options = ResolveOptions(process);
    const RobotModel model = LoadRobotModel(options.robot_urdf, options.robot_yaml);
    node = std::make_unique<TrackerNode>(options, model);
  } catch (const std::exception& e) {  // ConfigError, the robot files' and the options' errors
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  ConnectTrackerNode(&loop, node.get(), options.nmpc.control_period_s);
  spdlog::info("{}: {:.0f} Hz, horizon {} x {:.3f} s, latency {:.3f} s, stale state after {:.3f} s, budget {:.1f} ms, "
               "protective field {}",
               process.name, CycleRateHz(options), options.nmpc.horizon_steps, options.nmpc.step_s,
               options.nmpc.latency_s, options.nmpc.stale_state_s, options.nmpc.time_budget_s * 1e3,
               options.protective_field.enabled ? "on" : "off");
  const int code = loop.Run();
  std::printf("%s", node->Report().c_str());
  std::fflush(stdout);
  return code;
}
