#include "procs/mission/mission_options.h"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::mission {
namespace {

void Require(bool ok, double value, const std::string& source, const char* field, const char* what) {
  if (!ok || !std::isfinite(value)) throw ConfigError(source, field, fmt::format("must be finite and {}, got {}", what, value));
}

}  // namespace

void CheckMissionOptions(const MissionOptions& o, const std::string& source) {
  if (o.max_attempts < 1) throw ConfigError(source, "max_attempts", "must be >= 1");
  if (o.max_preemptions < 0) throw ConfigError(source, "max_preemptions", "must be >= 0");
  Require(o.retry_delay_s >= 0.0, o.retry_delay_s, source, "retry_delay_s", ">= 0");
  Require(o.step_timeout_s > 0.0, o.step_timeout_s, source, "step_timeout_s", "> 0");
  Require(o.tolerance.position_m >= 0.0, o.tolerance.position_m, source, "tolerance.position_m", ">= 0");
  Require(o.tolerance.orientation_rad >= 0.0, o.tolerance.orientation_rad, source, "tolerance.orientation_rad", ">= 0");
  Require(o.gripper_settle_s >= 0.0, o.gripper_settle_s, source, "gripper_settle_s", ">= 0");
  Require(o.arrival_settle_s > 0.0, o.arrival_settle_s, source, "arrival_settle_s", "> 0");
  Require(o.goal_repeat_period_s >= 0.0, o.goal_repeat_period_s, source, "goal_repeat_period_s", ">= 0");
  Require(o.status_period_s > 0.0, o.status_period_s, source, "status_period_s", "> 0");
  Require(o.start_timeout_s > 0.0, o.start_timeout_s, source, "start_timeout_s", "> 0");
}

MissionOptions LoadMissionOptions(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  MissionOptions o;
  o.source = path;
  YamlSection top(root, path);
  ReadRobotFiles(&top, &o.robot_urdf, &o.robot_yaml);
  top.Read("max_attempts", &o.max_attempts);
  top.Read("max_preemptions", &o.max_preemptions);
  top.Read("retry_delay_s", &o.retry_delay_s);
  top.Read("step_timeout_s", &o.step_timeout_s);
  YamlSection tolerance = top.Section("tolerance");
  tolerance.Read("position_m", &o.tolerance.position_m);
  tolerance.Read("orientation_rad", &o.tolerance.orientation_rad);
  tolerance.Finish();
  top.Read("gripper_settle_s", &o.gripper_settle_s);
  top.Read("arrival_settle_s", &o.arrival_settle_s);
  top.Read("goal_repeat_period_s", &o.goal_repeat_period_s);
  top.Read("status_period_s", &o.status_period_s);
  top.Read("wait_for_planner", &o.wait_for_planner);
  top.Read("start_timeout_s", &o.start_timeout_s);
  top.Finish();
  CheckMissionOptions(o, path);
  return o;
}

}  // namespace topay::mission
