#include "procs/tracker/tracker_options.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::tracker {
namespace {

void ReadArmPacing(YamlSection s, ArmPacingOptions* o) {
  s.Read("window_s", &o->window_s);
  s.Read("slack_m", &o->slack_m);
  s.Read("yaw_m_per_rad", &o->yaw_m_per_rad);
  s.Read("resolution_s", &o->resolution_s);
  s.Finish();
}

void ReadNmpc(YamlSection s, NmpcOptions* o) {
  s.Read("horizon_steps", &o->horizon_steps);
  s.Read("step_s", &o->step_s);
  s.Read("control_period_s", &o->control_period_s);
  s.Read("latency_s", &o->latency_s);
  s.Read("time_budget_s", &o->time_budget_s);
  s.Read("max_iterations", &o->max_iterations);
  s.Read("position_weight", &o->position_weight);
  s.Read("cross_track_weight", &o->cross_track_weight);
  s.Read("yaw_weight", &o->yaw_weight);
  s.Read("joint_weight", &o->joint_weight);
  s.Read("terminal_weight_factor", &o->terminal_weight_factor);
  s.Read("v_weight", &o->v_weight);
  s.Read("omega_weight", &o->omega_weight);
  s.Read("qd_weight", &o->qd_weight);
  s.Read("a_weight", &o->a_weight);
  s.Read("beta_weight", &o->beta_weight);
  s.Read("qdd_weight", &o->qdd_weight);
  s.Read("limit_weight", &o->limit_weight);
  s.Read("stale_state_s", &o->stale_state_s);
  s.Read("end_settle_s", &o->end_settle_s);
  ReadArmPacing(s.Section("arm_pacing"), &o->arm_pacing);
  s.Finish();
  try {
    o->Check();
  } catch (const std::invalid_argument& e) {
    throw ConfigError(s.source(), "nmpc", e.what());
  }
}

void ReadRebuild(YamlSection s, msgs::TrajectoryRebuildOptions* o) {
  int& panels = o->trajectory.integrator.panels_per_piece;
  s.Read("panels_per_piece", &panels);
  if (panels < 1) throw ConfigError(s.source(), s.FieldPath("panels_per_piece"), "must be >= 1");
  s.Read("coefficient_tolerance", &o->coefficient_tolerance);
  if (!(o->coefficient_tolerance > 0.0)) {
    throw ConfigError(s.source(), s.FieldPath("coefficient_tolerance"), "must be > 0");
  }
  s.Read("yaw0_tolerance_rad", &o->yaw0_tolerance_rad);
  if (!(o->yaw0_tolerance_rad > 0.0)) {
    throw ConfigError(s.source(), s.FieldPath("yaw0_tolerance_rad"), "must be > 0");
  }
  s.Finish();
}

void ReadPlannerWatch(YamlSection s, PlannerWatchOptions* o) {
  const YAML::Node names = s.Raw("process_names");
  if (names.IsDefined() && !names.IsNull()) {
    if (!names.IsSequence()) throw ConfigError(s.source(), s.FieldPath("process_names"), "expected a list of names");
    o->process_names.clear();
    for (const YAML::Node& name : names) {
      if (!name.IsScalar() || name.Scalar().empty()) {
        throw ConfigError(s.source(), s.FieldPath("process_names"), "expected non-empty process names");
      }
      o->process_names.push_back(name.Scalar());
    }
  }
  s.Read("silence_s", &o->silence_s);
  if (!(o->silence_s >= 0.0) || !std::isfinite(o->silence_s)) {
    throw ConfigError(s.source(), s.FieldPath("silence_s"), "must be finite and >= 0");
  }
  s.Finish();
}

void ReadProtectiveField(YamlSection s, ProtectiveFieldOptions* o) {
  s.Read("enabled", &o->enabled);
  s.Read("reaction_s", &o->reaction_s);
  s.Read("lookahead_m", &o->lookahead_m);
  s.Read("radial_margin_m", &o->radial_margin_m);
  s.Read("z_min_m", &o->z_min_m);
  s.Read("z_max_m", &o->z_max_m);
  s.Read("min_points", &o->min_points);
  s.Read("max_scan_age_s", &o->max_scan_age_s);
  s.Read("step_m", &o->step_m);
  s.Read("self_margin_m", &o->self_margin_m);
  s.Finish();
  try {
    o->Check();
  } catch (const std::invalid_argument& e) {
    throw ConfigError(s.source(), "protective_field", e.what());
  }
}

}  // namespace

double CycleRateHz(const TrackerOptions& options) { return 1.0 / options.nmpc.control_period_s; }

TrackerOptions LoadTrackerOptions(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  TrackerOptions o;
  o.source = path;
  YamlSection top(root, path);
  ReadRobotFiles(&top, &o.robot_urdf, &o.robot_yaml);
  ReadNmpc(top.Section("nmpc"), &o.nmpc);
  ReadRebuild(top.Section("rebuild"), &o.rebuild);
  top.Read("rest_command", &o.rest_command);
  if (!(o.rest_command > 0.0) || !std::isfinite(o.rest_command)) {
    throw ConfigError(path, "rest_command", "must be finite and > 0");
  }
  top.Read("lost_position_m", &o.lost_position_m);
  if (!(o.lost_position_m >= 0.0) || !std::isfinite(o.lost_position_m)) {
    throw ConfigError(path, "lost_position_m", "must be finite and >= 0");
  }
  for (const auto& [key, value] : {std::pair{"jump_position_m", &o.jump_position_m}, std::pair{"jump_yaw_rad", &o.jump_yaw_rad}}) {
    top.Read(key, value);
    if (!(*value >= 0.0) || !std::isfinite(*value)) throw ConfigError(path, key, "must be finite and >= 0");
  }
  ReadPlannerWatch(top.Section("planner_watch"), &o.planner_watch);
  ReadProtectiveField(top.Section("protective_field"), &o.protective_field);
  top.Finish();
  return o;
}

}  // namespace topay::tracker
