// topay-kinematic-sim: publishes the robot model's state (ROBOT_STATE) from velocity commands
// (CONTROL_COMMAND), and at state_rate_hz while no command arrives. The first process of the
// simulation graph (config/graphs/sim.yaml). Exit codes: 0, 1 config error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "procs/kinematic_sim/kinematic_model.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

using namespace topay;

int main(int argc, char** argv) {
  CLI::App app{"topay-kinematic-sim: the robot model's state from velocity commands"};
  procs::ProcessOptions options;
  procs::AddCommonFlags(&app, "topay-kinematic-sim", &options);
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  kinsim::KinematicModelOptions model_options;
  try {
    if (!options.config_path.empty()) model_options = kinsim::LoadKinematicModelOptions(options.config_path);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(options);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  kinsim::KinematicModel model(model_options);
  std::int64_t rejected = 0;
  procs::ProcessLoop::Clock::time_point last_command{};
  auto publish = [&](std::int64_t utime) {
    msgs::RobotStateEstimate state = model.state();
    state.utime = utime;
    const robot_state_t msg = msgs::ToMessage(state);
    loop.lcm().publish(std::string(channels::ROBOT_STATE), &msg);
  };
  loop.Subscribe<control_command_t>(std::string(channels::CONTROL_COMMAND), [&](const control_command_t& cmd) {
    if (!model.Apply(cmd)) {
      ++rejected;
      spdlog::warn("ignored a command with {} joints, non-finite values or rates beyond {} (m/s, rad/s)", cmd.num_joints,
                   kinsim::KinematicModel::kMaxRate);
      return;
    }
    last_command = procs::ProcessLoop::Clock::now();
    publish(model.state().utime);
  });
  if (model_options.state_rate_hz > 0.0) {
    const double period_s = 1.0 / model_options.state_rate_hz;
    loop.AddTimer(period_s, [&, period_s] {  // period_s by value: the timer outlives this block
      if (procs::ProcessLoop::Clock::now() - last_command > std::chrono::duration<double>(period_s)) {
        publish(procs::NowUtime());
      }
    });
  }
  loop.AddTimer(1.0, [&] {
    const WholeBodyState& s = model.state().state;
    loop.SetHealth(rejected > 0 ? heartbeat_t::WARN : heartbeat_t::OK,
                   fmt::format("commands {} (rejected {}), x {:.2f} m y {:.2f} m yaw {:.2f} rad",
                               model.commands_applied(), rejected, s.x_m, s.y_m, s.yaw_rad));
  });
  loop.SetHealth(heartbeat_t::OK, "waiting for commands");
  spdlog::info("{}: publishing {} on {}", options.name, channels::ROBOT_STATE, options.lcm_url.empty() ? "the default LCM URL" : options.lcm_url);
  return loop.Run();
}
