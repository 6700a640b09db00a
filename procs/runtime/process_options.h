#pragma once
// The flags every process of the graph shares (--lcm-url, --config, --name, --help) and the
// exit codes of the stack.

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace topay::procs {

/// Exit codes of every process: 0 success, 1 config or file error, 2 usage error.
enum ExitCode : int { kExitOk = 0, kExitConfigError = 1, kExitUsageError = 2 };

/// What the common flags set. Defaults are documented per field.
struct ProcessOptions {
  /// Name in heartbeats and logs. Default: $TOPAY_PROCESS_NAME (set by topay-launch to the
  /// graph's process name), else the program's default name.
  std::string name;
  /// LCM URL. Empty (default): $LCM_DEFAULT_URL, else LCM's own default (udpm).
  std::string lcm_url;
  /// YAML config file. Empty (default): the process's built-in defaults.
  std::string config_path;
  /// Period of the HEARTBEAT, seconds (default 1 s, the graph's contract).
  double heartbeat_period_s = 1.0;
  /// mlockall(MCL_CURRENT | MCL_FUTURE) at start-up. Default: $TOPAY_MLOCKALL == "1" (set by
  /// topay-launch for processes with `mlockall: true`; it cannot be applied across exec).
  bool mlockall = false;
};

/// Adds --lcm-url, --config and --name to `app` (CLI11 adds --help), writing into *options,
/// and fills the environment defaults (TOPAY_PROCESS_NAME, TOPAY_MLOCKALL), `default_name`
/// when no name is given.
void AddCommonFlags(CLI::App* app, const std::string& default_name, ProcessOptions* options);

/// The configuration folder: $TOPAY_CONFIG_DIR if set and not empty, else `built_in` (the
/// source tree's config/, compiled into each process).
std::string ConfigDir(const std::string& built_in);

/// Fills an empty robot URDF / robot YAML path with the shipped robot's files in `config_dir`
/// (robot/topay_mm.urdf, robot/topay_mm.yaml).
void DefaultRobotFiles(const std::string& config_dir, std::string* robot_urdf, std::string* robot_yaml);

/// Parses argv with `app`. Returns nullopt to go on, or the exit code to return from main:
/// 0 after --help (printed), 2 after a usage error (printed with the usage hint).
std::optional<int> ParseFlags(CLI::App* app, int argc, char** argv);

}  // namespace topay::procs
