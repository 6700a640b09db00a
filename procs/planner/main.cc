// topay-planner: the onboard planner of the graph (docs/planner.md). GOAL, ROBOT_STATE,
// MAP_UPDATE and TRACKER_STATUS in; TRAJECTORY and PLANNER_STATUS out. Plans on the live map
// (the mapper's voxels: distance fields updated in batches, exact voxel boxes for its own
// validation) on a planning thread; replans on a collision ahead, drift or a new goal, from the
// moving robot; a stopping trajectory when the way ahead is blocked and no new plan comes.
// Exit codes: 0, 1 config or file error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

#include "core/common/error.h"
#include "core/control/tracked_robot_prediction.h"
#include "core/control/tracker_limits.h"
#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"
#include "procs/planner/plan_worker.h"
#include "procs/planner/planner_node.h"
#include "procs/planner/planner_process_options.h"
#include "procs/planner/stop_planner.h"
#include "procs/runtime/process_loop.h"
#include "procs/tracker/tracker_options.h"

using namespace topay;
using namespace topay::planner;

namespace {

PlannerProcessOptions ResolveOptions(const procs::ProcessOptions& process) {
  PlannerProcessOptions o =
      process.config_path.empty() ? PlannerProcessOptions{} : LoadPlannerProcessOptions(process.config_path);
  const std::string config_dir = procs::ConfigDir(TOPAY_CONFIG_DIR);
  procs::DefaultRobotFiles(config_dir, &o.robot_urdf, &o.robot_yaml);
  if (o.planner_config.empty()) o.planner_config = config_dir + "/planner/topay.yaml";
  if (o.tracker_config.empty()) o.tracker_config = config_dir + "/tracker/tracker.yaml";
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-planner: whole-body plans on the live map, replanning, safe stop"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-planner", &process);
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  PlannerProcessOptions options;
  WholeBodyPlannerOptions planner_options;
  std::unique_ptr<RobotModel> model;
  std::unique_ptr<Kinematics> kinematics;
  std::unique_ptr<TrackedRobotPredictor> tracked_start;  // triggers.drift_start tracked
  try {
    options = ResolveOptions(process);
    planner_options = LoadPlannerOptions(options.planner_config);
    AdaptPlannerOptions(options, &planner_options);
    model = std::make_unique<RobotModel>(LoadRobotModel(options.robot_urdf, options.robot_yaml));
    if (options.triggers.drift_start_tracked) {  // the tracker's NMPC at the robot's full limits
      tracked_start = std::make_unique<TrackedRobotPredictor>(tracker::LoadTrackerOptions(options.tracker_config).nmpc,
                                                               MakeTrackerLimits(*model));
    }
    ApplyPlanLimits(options, model.get(), &planner_options);
    kinematics = std::make_unique<Kinematics>(*model);
  } catch (const std::exception& e) {  // ConfigError and the robot files' errors
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  const StopPlanner stop_planner(*model, planner_options.base_limits.value_or(model->base_limits));
  PlanWorker worker(*kinematics, planner_options, options.map.unknown, FieldUpdatePeriod(options),
                    options.map.slice_m);
  PlannerNode node(&loop, &worker, *kinematics, stop_planner, options, tracked_start.get());
  spdlog::info("{}: robot {}, planner {}, unknown voxels {}, replanning budget {:.2f} s, {:.0f} % of the "
               "acceleration limits, drift replans from the {} robot{}", process.name, model->name,
               options.planner_config, ToString(options.map.unknown),
               options.timing.replan_budget_s, 100.0 * options.limits.acceleration_share,
               tracked_start ? "tracked (" + options.tracker_config + ")" : std::string("carried"),
               options.deterministic.enabled ? "; DETERMINISTIC mode (message time, synchronous plans: replay "
                                               "and tests, not the robot)" : "");
  const int code = loop.Run();
  // Deterministic mode: every message received gets its outputs, however soon it is stopped.
  if (options.deterministic.enabled) node.FinishInbox();
  std::printf("%s", node.Report().c_str());
  std::fflush(stdout);
  return code;
}
