// topay-command-pattern: publishes seeded velocity commands on CONTROL_COMMAND (--count of
// them at --rate-hz, then only heartbeats). For tests, log round trips and demos.
// Exit codes: 0, 1 LCM error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "procs/command_pattern/command_pattern.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

using namespace topay;

int main(int argc, char** argv) {
  CLI::App app{"topay-command-pattern: seeded velocity commands on CONTROL_COMMAND"};
  procs::ProcessOptions options;
  procs::AddCommonFlags(&app, "topay-command-pattern", &options);
  pattern::CommandPatternOptions pattern_options;
  double rate_hz = 20.0;
  std::int64_t count = 0;
  double delay_s = 0.0;
  app.add_option("--seed", pattern_options.seed, "pattern seed")->capture_default_str();
  app.add_option("--rate-hz", rate_hz, "commands per second")->capture_default_str()->check(CLI::Range(0.1, 10000.0));
  app.add_option("--count", count, "number of commands (0: unlimited)")->capture_default_str();
  app.add_option("--delay", delay_s, "seconds before the first command")->capture_default_str();
  app.add_option("--joints", pattern_options.num_joints, "joints per command")->capture_default_str();
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  procs::ProcessLoop loop(options);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  std::int64_t sent = 0;
  const auto begin = procs::ProcessLoop::Clock::now() + std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(delay_s));
  loop.AddTimer(1.0 / rate_hz, [&] {
    if ((count > 0 && sent >= count) || procs::ProcessLoop::Clock::now() < begin) return;
    const control_command_t cmd = pattern::PatternCommand(pattern_options, sent, procs::NowUtime());
    loop.lcm().publish(std::string(channels::CONTROL_COMMAND), &cmd);
    ++sent;
    loop.SetHealth(heartbeat_t::OK, fmt::format("sent {} commands", sent));
  });
  loop.SetHealth(heartbeat_t::OK, "sent 0 commands");
  return loop.Run();
}
