#include "procs/sim/command_replay.h"

#include <lcm/lcm-cpp.hpp>

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
                            std::int64_t epoch_utime, double end_s) {
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
    core->Step();
  }
  return rejected;
}

}  // namespace topay::simproc
