#include "procs/runtime/process_options.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>

namespace topay::procs {

std::string ConfigDir(const std::string& built_in) {
  const char* env = std::getenv("TOPAY_CONFIG_DIR");
  return env != nullptr && *env != '\0' ? env : built_in;
}

void DefaultRobotFiles(const std::string& config_dir, std::string* robot_urdf, std::string* robot_yaml) {
  if (robot_urdf->empty()) *robot_urdf = config_dir + "/robot/topay_mm.urdf";
  if (robot_yaml->empty()) *robot_yaml = config_dir + "/robot/topay_mm.yaml";
}

void AddCommonFlags(CLI::App* app, const std::string& default_name, ProcessOptions* options) {
  const char* env_name = std::getenv("TOPAY_PROCESS_NAME");
  options->name = (env_name != nullptr && *env_name != '\0') ? env_name : default_name;
  const char* env_mlock = std::getenv("TOPAY_MLOCKALL");
  options->mlockall = env_mlock != nullptr && std::string(env_mlock) == "1";
  app->add_option("--lcm-url", options->lcm_url,
                  "LCM URL (default: $LCM_DEFAULT_URL, else LCM's udpm default)");
  app->add_option("--config", options->config_path, "YAML config file");
  app->add_option("--name", options->name, "process name in heartbeats and logs")
      ->capture_default_str();
}

std::optional<int> ParseFlags(CLI::App* app, int argc, char** argv) {
  try {
    app->parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    app->exit(e);
    return kExitOk;
  } catch (const CLI::CallForAllHelp& e) {
    app->exit(e);
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    app->exit(e);
    return kExitUsageError;
  }
  return std::nullopt;
}

}  // namespace topay::procs
