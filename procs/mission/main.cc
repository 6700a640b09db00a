// topay-mission: runs a mission (a task list from YAML, docs/mission.md) on the graph. Sends
// GOALs and waits for arrival (PLANNER_STATUS, ROBOT_STATE, TRACKER_STATUS), GRIPPER_COMMANDs,
// waits; reports on MISSION_STATUS and the terminal, and a summary at the end.
// Exit codes: 0 mission succeeded, 1 config or file error, 2 usage error, 3 mission failed,
// 4 aborted (SIGINT / SIGTERM).

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "core/io/robot_loader.h"
#include "procs/mission/mission_node.h"
#include "procs/mission/mission_options.h"
#include "procs/mission/mission_spec.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

using namespace topay;
using namespace topay::mission;

namespace {

constexpr int kExitMissionFailed = 3;
constexpr int kExitMissionAborted = 4;

MissionOptions ResolveOptions(const procs::ProcessOptions& process) {
  MissionOptions o = process.config_path.empty() ? MissionOptions{} : LoadMissionOptions(process.config_path);
  const std::string config_dir = procs::ConfigDir(TOPAY_CONFIG_DIR);
  procs::DefaultRobotFiles(config_dir, &o.robot_urdf, &o.robot_yaml);
  return o;
}

int ExitCodeOf(const MissionNode& node) {
  switch (node.state()) {
    case mission_status_t::SUCCEEDED: return procs::kExitOk;
    case mission_status_t::ABORTED: return kExitMissionAborted;
    default: return kExitMissionFailed;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-mission: runs a task list (go to poses, gripper, wait, home) on the graph"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-mission", &process);
  std::string mission_path;
  app.add_option("--mission", mission_path, "mission YAML (docs/mission.md)")->required();
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  MissionOptions options;
  Mission mission;
  std::unique_ptr<RobotModel> model;
  std::unique_ptr<Kinematics> kinematics;
  try {
    options = ResolveOptions(process);
    mission = LoadMission(mission_path);
    model = std::make_unique<RobotModel>(LoadRobotModel(options.robot_urdf, options.robot_yaml));
    kinematics = std::make_unique<Kinematics>(*model);
    CheckMissionForRobot(mission, kinematics->num_joints());
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
  MissionOutputs outputs;
  outputs.goal = [&lcm](const goal_t& m) { lcm.publish(std::string(channels::GOAL), &m); };
  outputs.gripper = [&lcm](const gripper_command_t& m) { lcm.publish(std::string(channels::GRIPPER_COMMAND), &m); };
  outputs.status = [&lcm](const mission_status_t& m) { lcm.publish(std::string(channels::MISSION_STATUS), &m); };
  MissionNode node(mission, *kinematics, options, outputs, procs::NowUtime());

  // After every input: the heartbeat's status line, and the loop ends once the mission is over.
  auto after = [&] {
    std::int8_t health = heartbeat_t::OK;
    if (node.state() == mission_status_t::FAILED) health = heartbeat_t::ERROR;
    loop.SetHealth(health, node.StatusLine());
    if (node.finished()) loop.Stop();
  };
  loop.Subscribe<robot_state_t>(std::string(channels::ROBOT_STATE), [&](const robot_state_t& m) {
    node.OnRobotState(m, procs::NowUtime());
    after();
  });
  loop.Subscribe<planner_status_t>(std::string(channels::PLANNER_STATUS), [&](const planner_status_t& m) {
    node.OnPlannerStatus(m, procs::NowUtime());
    after();
  });
  loop.Subscribe<tracker_status_t>(std::string(channels::TRACKER_STATUS), [&](const tracker_status_t& m) {
    node.OnTrackerStatus(m, procs::NowUtime());
    after();
  });
  loop.AddTimer(0.05, [&] {
    node.Tick(procs::NowUtime());
    after();
  });
  spdlog::info("{}: mission '{}' from {} ({} steps), max {} attempts per goal, step timeout {:.0f} s", process.name,
               mission.name, mission_path, mission.steps.size(), options.max_attempts, options.step_timeout_s);

  const int loop_code = loop.Run();
  if (!node.finished()) node.Abort(loop_code == 0 ? "stopped by a signal" : "the LCM loop failed", procs::NowUtime());
  std::printf("%s", node.Summary().c_str());
  std::fflush(stdout);
  if (loop_code != 0 && node.state() != mission_status_t::SUCCEEDED) return loop_code;
  return ExitCodeOf(node);
}
