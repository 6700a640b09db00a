#pragma once
// Running one program to completion from a tool: its output into a file, a callback while it
// runs (progress), a time limit, and the interrupt forwarded.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace topay::tools {

struct ChildCommandOptions {
  std::string output_path;       ///< stdout and stderr go here (truncated); empty: inherited
  double timeout_s = 0.0;        ///< > 0: SIGINT after this long, SIGKILL 10 s later
  double poll_period_s = 0.2;    ///< how often `on_poll` runs while the child runs, s
  std::function<void()> on_poll; ///< called every poll period and once after the exit
  /// Returns true when the caller wants the child stopped (e.g. after Ctrl-C): it gets SIGINT.
  std::function<bool()> stop_requested;
};

struct ChildCommandResult {
  int exit_code = -1;        ///< its exit code; 128 + signal if it was killed
  bool timed_out = false;    ///< the time limit sent it SIGINT
  std::string error;         ///< non-empty if it could not be started (names the program)
};

/// Runs argv[0] (searched in PATH) with argv and waits for it.
ChildCommandResult RunChildCommand(const std::vector<std::string>& argv, const ChildCommandOptions& options);

}  // namespace topay::tools
