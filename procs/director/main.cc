// topay-director: scripted disturbances for demos and tests (docs/director.md). Reads the room
// the simulator runs (--scene, scene JSON) and a script (--config, config/director/); follows
// MISSION_STATUS, TRAJECTORY and ROBOT_STATE and publishes SIM_EVENTs (a box on the robot's
// route while a given mission step runs). Exit codes: 0 clean stop (SIGINT / SIGTERM),
// 1 config, robot or scene file error (or LCM could not be opened), 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <memory>
#include <optional>

#include "core/io/robot_loader.h"
#include "procs/director/director_node.h"
#include "procs/director/director_options.h"
#include "procs/runtime/process_loop.h"
#include "sim/scenes/scene_json.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

using namespace topay;
using namespace topay::director;

namespace {

DirectorOptions ResolveOptions(const procs::ProcessOptions& process) {
  const std::string config_dir = procs::ConfigDir(TOPAY_CONFIG_DIR);
  const std::string path = process.config_path.empty() ? config_dir + "/director/pick_place.yaml" : process.config_path;
  DirectorOptions o = LoadDirectorOptions(path);
  procs::DefaultRobotFiles(config_dir, &o.robot_urdf, &o.robot_yaml);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-director: scripted disturbances (a box on the robot's route) for demos and tests"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-director", &process);
  std::string scene_path;
  app.add_option("--scene", scene_path, "the room the simulator runs (scene JSON, as topay-sim --scene)")->required();
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  DirectorOptions options;
  Scene scene;
  std::unique_ptr<RobotModel> model;
  std::unique_ptr<Kinematics> kinematics;
  try {
    options = ResolveOptions(process);
    scene = ReadSceneJson(scene_path);
    model = std::make_unique<RobotModel>(LoadRobotModel(options.robot_urdf, options.robot_yaml));
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
  lcm::LCM& lcm = loop.lcm();
  DirectorOutputs outputs;
  outputs.event = [&lcm](const sim_event_t& m) { lcm.publish(std::string(channels::SIM_EVENT), &m); };
  outputs.log = [](bool warning, const std::string& line) {
    if (warning) {
      spdlog::warn("{}", line);
    } else {
      spdlog::info("{}", line);
    }
  };
  const std::size_t num_events = options.events.size();
  const double tick_period_s = options.tick_period_s;
  DirectorNode node(std::move(options), std::move(scene), *kinematics, outputs);

  auto after = [&] {
    loop.SetHealth(node.events_given_up() > 0 ? heartbeat_t::WARN : heartbeat_t::OK, node.StatusLine());
  };
  loop.Subscribe<mission_status_t>(std::string(channels::MISSION_STATUS), [&](const mission_status_t& m) {
    node.OnMissionStatus(m);
  });
  loop.Subscribe<poly_trajectory_t>(std::string(channels::TRAJECTORY), [&](const poly_trajectory_t& m) {
    node.OnTrajectory(m);
  });
  loop.Subscribe<robot_state_t>(std::string(channels::ROBOT_STATE), [&](const robot_state_t& m) {
    node.OnRobotState(m);
  });
  loop.AddTimer(tick_period_s, [&] {
    node.Tick(procs::NowUtime());
    after();
  });
  after();
  spdlog::info("{}: {} scripted event(s), scene {}", process.name, num_events, scene_path);
  const int code = loop.Run();
  spdlog::info("{}: {} box(es) placed, {} event(s) given up", process.name, node.boxes_placed(), node.events_given_up());
  return code;
}
