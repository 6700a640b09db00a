// topay-scenario: the pick-and-place scenario of a seeded unseen Tables room (docs/director.md):
// writes DIR/room.json (topay-sim --scene), DIR/mission.yaml (topay-mission --mission) and
// DIR/scenario.json (seed, goals, end-effector poses), and prints one line per goal.
// Exit codes: 0 written, 1 no scenario for the seed or a config / file error (the message says
// what), 2 usage error.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "core/io/robot_loader.h"
#include "sim/scenarios/pick_place_scenario.h"
#include "tools/common/tool_cli.h"
#include "tools/topay_scenario/scenario_files.h"

using namespace topay;

int main(int argc, char** argv) {
  CLI::App app{"topay-scenario: the pick-and-place scenario of a seeded unseen Tables room"};
  app.footer(tools::ExitCodesFooter(false));
  const std::string config_dir = tools::ConfigDir(TOPAY_CONFIG_DIR);
  std::uint64_t seed = 0;
  std::string out_dir;
  std::string config = config_dir + "/scenarios/pick_place.yaml";
  std::string urdf = config_dir + "/robot/topay_mm.urdf";
  std::string robot_yaml = config_dir + "/robot/topay_mm.yaml";
  app.add_option("--seed", seed, "room and goal seed")->required()->check(tools::NonNegativeInteger());
  app.add_option("--out", out_dir, "folder for room.json, mission.yaml and scenario.json")->required();
  app.add_option("--config", config, "scenario options (YAML)")->capture_default_str();
  app.add_option("--robot", urdf, "robot URDF")->capture_default_str();
  app.add_option("--robot-yaml", robot_yaml, "robot collision / limits YAML")->capture_default_str();
  if (const std::optional<int> code = tools::ParseCommandLine(app, argc, argv, "topay-scenario")) return *code;
  try {
    const PickPlaceScenarioOptions options = LoadPickPlaceScenarioOptions(config);
    const RobotModel model = LoadRobotModel(urdf, robot_yaml);
    const Kinematics kinematics(model);
    const PickPlaceScenario s = MakePickPlaceScenario(options, seed, kinematics);
    scenario::WriteScenarioFiles(out_dir, s, options);
    const Eigen::Vector2d p_pickup(s.pickup.state.x_m, s.pickup.state.y_m);
    std::printf("%s\n", scenario::GoalLine("pickup", s, s.pickup, s.p_W_start_m, "start").c_str());
    std::printf("%s\n", scenario::GoalLine("dropoff", s, s.dropoff, p_pickup, "pickup").c_str());
    std::printf("wrote %s/room.json, mission.yaml, scenario.json (seed %llu)\n", out_dir.c_str(),
                static_cast<unsigned long long>(seed));
    return tools::kExitSuccess;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "topay-scenario: %s\n", e.what());
    return tools::kExitFileError;
  }
}
