#include "procs/sim/command_replay.h"

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>

#include "core/common/error.h"
#include "procs/sim/sim_messages.h"
#include "topay_msgs/checked_decode.h"

namespace topay::simproc {

std::vector<TimedCommand> ReadCommandLog(const std::string& path, const std::string& channel,
                                         std::int64_t* skipped) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw ConfigError(path, "", "cannot open the LCM log");
  std::vector<TimedCommand> commands;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    if (event->channel != channel) continue;
    std::string error;
    const std::optional<control_command_t> cmd = CheckedDecode<control_command_t>(event->data, event->datalen, &error);
    if (!cmd) {
      if (skipped != nullptr) ++*skipped;
      continue;
    }
    commands.push_back({cmd->utime, *cmd});
  }
  return commands;
}

std::int64_t ReplayCommands(SimCore* core, const std::vector<TimedCommand>& commands,
                            std::int64_t epoch_utime, double end_s, std::vector<double>* step_us) {
  const double step_s = core->plant().step_s();
  const std::int64_t end_step = std::llround(end_s / step_s);
  std::int64_t rejected = 0;
  std::size_t next = 0;
  while (true) {
    // Commands whose time has come (at or before the current step's time) go in before the step.
    while (next < commands.size()) {
      const double t_s = static_cast<double>(commands[next].utime - epoch_utime) * 1e-6;
      if (std::ceil(t_s / step_s - 1e-9) > static_cast<double>(core->steps())) break;
      if (!core->Command(ToActuatorCommand(commands[next].command)).empty()) ++rejected;
      ++next;
    }
    if (core->steps() >= end_step) break;
    if (step_us == nullptr) {
      core->Step();
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    core->Step();
    step_us->push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  return rejected;
}

}  // namespace topay::simproc

namespace topay::simproc {
namespace {

std::string Percentiles(std::vector<double> v, const char* what) {
  if (v.empty()) return std::string(what) + ": none";
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) { return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))]; };
  char text[256];
  std::snprintf(text, sizeof text, "%s: median %.2f us, p95 %.2f us, max %.0f us over %zu steps", what, at(0.5), at(0.95),
                v.back(), v.size());
  return text;
}

}  // namespace

std::string StepTimeSummary(const std::vector<double>& step_us, std::int64_t steps_per_scan) {
  std::vector<double> plain, scanned;
  for (std::size_t i = 0; i < step_us.size(); ++i) {
    const std::int64_t k = static_cast<std::int64_t>(i) + 1;  // the step's number after it ran
    (steps_per_scan > 0 && k % steps_per_scan == 0 ? scanned : plain).push_back(step_us[i]);
  }
  return Percentiles(plain, "core step (plant, events, monitor, localisation)") + "\n" +
         Percentiles(scanned, "core step with a LiDAR scan");
}

}  // namespace topay::simproc
