// topay-sim: the simulator of the graph (docs/simulator.md). The world (scene file or generated
// room), the robot plant at 500 Hz, localisation, LiDAR, the ground-truth collision monitor and
// scripted events; CONTROL_COMMAND (or, with --follow, TRAJECTORY followed exactly) and SIM_EVENT
// in; ROBOT_STATE, BASE_POSE, POINT_CLOUD, SIM_CONTACT, SIM_STATUS out. Exit codes: 0, 1 config or file error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdlib>

#include "core/common/error.h"
#include "procs/runtime/process_loop.h"
#include "procs/sim/command_replay.h"
#include "procs/sim/output_digest.h"
#include "procs/sim/sensor_factory.h"
#include "procs/sim/sim_node.h"
#include "procs/sim/sim_options.h"
#include "procs/sim/sim_setup.h"
#include "topay_msgs/channels.h"

using namespace topay;

namespace {

struct Flags {
  std::string scene, robot_urdf, robot_yaml, events, replay_log, plant_input, checkpoint;
  std::optional<std::uint64_t> seed;
  std::optional<double> rate, duration_s;
  std::optional<std::int64_t> start_utime;
  bool max_speed = false;
  bool follow = false;
};

void AddSimFlags(CLI::App* app, Flags* f) {
  app->add_option("--scene", f->scene, "tables | cuboids (generated, with --seed) | a scene JSON file");
  app->add_option("--seed", f->seed, "seed of a generated scene (default: the config's scene.seed)");
  app->add_option("--robot", f->robot_urdf, "robot URDF (default: the config's, else the shipped TopAY robot)");
  app->add_option("--robot-yaml", f->robot_yaml, "robot YAML (collision model, limits)");
  app->add_option("--events", f->events, "scripted events YAML (docs/simulator.md)");
  auto* rate = app->add_option("--rate", f->rate, "real-time factor (default 1; the config's `rate`)")->check(CLI::PositiveNumber);
  app->add_flag("--max-speed", f->max_speed, "step as fast as possible (no real-time pacing)")->excludes(rate);
  app->add_option("--duration", f->duration_s, "stop after this much sim time, s")->check(CLI::PositiveNumber);
  app->add_option("--start-utime", f->start_utime, "utime of sim time 0, us (default: the wall clock at start)");
  auto* replay = app->add_option("--replay-commands", f->replay_log,
                                 "lockstep: feed the CONTROL_COMMANDs of this LCM log at their own times, as fast as "
                                 "possible, print the output digests and exit (no LCM traffic)");
  app->add_flag("--follow", f->follow,
                "ideal follower: the robot follows TRAJECTORY exactly instead of CONTROL_COMMAND (the config's "
                "`follow`)")
      ->excludes(replay);
  app->add_option("--plant-input", f->plant_input,
                  "control_command (default) | actuators: the CAN mode, ACTUATOR_COMMAND + GRIPPER_COMMAND in, "
                  "SIM_PLANT_STATE + GRIPPER_STATE out, no ROBOT_STATE (the config's `plant_input`)")
      ->check(CLI::IsMember({"control_command", "actuators"}));
  app->add_option("--checkpoint", f->checkpoint,
                  "the plant's checkpoint: read at start if it exists (a restarted simulator continues where the "
                  "robot was), written every status period");
}

simproc::SimOptions ResolveOptions(const procs::ProcessOptions& process, const Flags& f) {
  simproc::SimOptions o = process.config_path.empty() ? simproc::SimOptions{} : simproc::LoadSimOptions(process.config_path);
  const std::string config_dir = procs::ConfigDir(TOPAY_CONFIG_DIR);
  procs::DefaultRobotFiles(config_dir, &o.robot_urdf, &o.robot_yaml);
  if (!f.scene.empty()) o.scene = f.scene;
  if (f.seed) o.scene_seed = *f.seed;
  if (!f.robot_urdf.empty()) o.robot_urdf = f.robot_urdf;
  if (!f.robot_yaml.empty()) o.robot_yaml = f.robot_yaml;
  if (!f.events.empty()) o.events_file = f.events;
  if (f.rate) o.rate = *f.rate;
  if (f.max_speed) o.rate = 0.0;
  if (f.start_utime) o.start_utime = *f.start_utime;
  if (f.follow) o.follow = true;
  if (!f.plant_input.empty()) o.plant_input = f.plant_input;
  o.checkpoint_file = f.checkpoint;
  if (o.follow && o.plant_input == "actuators") throw ConfigError(o.source, "plant_input", "actuators and --follow exclude each other");
  return o;
}

int ReplayCommandLog(simproc::SimAssembly* sim, const std::string& log, double duration_s) {
  std::int64_t skipped = 0;
  const std::vector<simproc::TimedCommand> commands = simproc::ReadCommandLog(log, std::string(channels::CONTROL_COMMAND), &skipped);
  if (commands.empty()) throw ConfigError(log, "CONTROL_COMMAND", "no commands in the log");
  simproc::OutputDigest digest;
  sim->core->SetListener(&digest);
  const double end_s = duration_s > 0.0 ? duration_s
                                        : (commands.back().utime - commands.front().utime) * 1e-6 + 1.0;
  std::vector<double> step_us;
  const std::int64_t rejected = simproc::ReplayCommands(sim->core.get(), commands, commands.front().utime, end_s, &step_us);
  std::printf("replay: %zu commands (%lld undecodable skipped, %lld rejected), %.3f s sim time\n", commands.size(),
              static_cast<long long>(skipped), static_cast<long long>(rejected), sim->core->time_s());
  std::printf("digest states %016llx (%lld) scans %016llx (%lld) contacts %016llx (%lld) events %016llx (%lld)\n",
              static_cast<unsigned long long>(digest.states()), static_cast<long long>(digest.num_states),
              static_cast<unsigned long long>(digest.scans()), static_cast<long long>(digest.num_scans),
              static_cast<unsigned long long>(digest.contacts()), static_cast<long long>(digest.num_contacts),
              static_cast<unsigned long long>(digest.events()), static_cast<long long>(digest.num_events));
  std::printf("%s\n", simproc::StepTimeSummary(step_us, sim->core->steps_per_scan()).c_str());
  return procs::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-sim: world, robot plant (500 Hz), localisation, LiDAR, collision monitor, scripted events"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-sim", &process);
  Flags flags;
  AddSimFlags(&app, &flags);
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  simproc::SimOptions options;
  simproc::SimAssembly sim;
  try {
    options = ResolveOptions(process, flags);
    sim = simproc::AssembleSim(options);
    if (!flags.replay_log.empty() && options.follow) {
      throw ConfigError(options.source, "follow", "--replay-commands replays CONTROL_COMMANDs: not in follow mode");
    }
    if (!flags.replay_log.empty()) return ReplayCommandLog(&sim, flags.replay_log, flags.duration_s.value_or(0.0));
  } catch (const ConfigError& e) {
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  spdlog::info("{}: robot {} ({} joints), scene {}, {} scripted events, LiDAR {}, monitor {}, rate {}, driven by {}",
               process.name, sim.model->name, sim.model->num_joints(), sim.scene_description, sim.num_scripted_events,
               sim.core->has_lidar() ? "on" : "off", sim.core->contact_sensor() != nullptr ? "on" : "off",
               options.rate > 0.0 ? fmt::format("{}x real time", options.rate) : std::string("as fast as possible"),
               options.follow                          ? "TRAJECTORY (ideal follower)"
               : options.plant_input == "actuators"    ? "ACTUATOR_COMMAND + GRIPPER_COMMAND (CAN mode)"
                                                        : "CONTROL_COMMAND");

  if (!sim.resumed_from.empty()) spdlog::warn("{}: resumed from the plant checkpoint {}", process.name, sim.resumed_from);
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  simproc::SimNodeOptions node_options;
  node_options.start_utime = options.start_utime;
  node_options.rate = options.rate;
  node_options.max_catch_up_steps = options.max_catch_up_steps;
  node_options.status_rate_hz = options.status_rate_hz;
  node_options.duration_s = flags.duration_s.value_or(0.0);
  node_options.joint_names = sim.model->joint_names;
  node_options.follow = options.follow;
  node_options.follower = options.follower;
  node_options.actuator_input = options.plant_input == "actuators";
  node_options.plant_state_rate_hz = options.plant_state_rate_hz;
  node_options.checkpoint_file = options.checkpoint_file;
  simproc::SimNode node(&loop, sim.core.get(), node_options);
  const int code = loop.Run();
  node.Finish();
  std::printf("%s\n", node.FinalReport().c_str());
  std::fflush(stdout);
  return code;
}
