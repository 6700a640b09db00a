#include "procs/planner/planner_process_options.h"

#include <cmath>
#include <filesystem>

#include "core/common/error.h"
#include "core/io/yaml_section.h"
#include "core/planner/deterministic_options.h"

namespace topay::planner {
namespace {

void ReadMap(YamlSection s, PlannerMapOptions* o) {
  std::string unknown = ToString(o->unknown);
  s.Read("unknown", &unknown);
  const std::optional<UnknownVoxelPolicy> policy = ParseUnknownVoxelPolicy(unknown);
  if (!policy) {
    throw ConfigError(s.source(), s.FieldPath("unknown"),
                      "expected free, occupied or occupied_in_base_bands, got '" + unknown + "'");
  }
  o->unknown = *policy;
  s.Read("field_update_period_s", &o->field_update_period_s);
  s.Read("slice_m", &o->slice_m);
  s.Read("flush_all_from_rest", &o->flush_all_from_rest);
  s.Read("start_arm_overlap_m", &o->start_arm_overlap_m);
  s.Read("start_arm_escape_overlap_m", &o->start_arm_escape_overlap_m);
  s.Read("fresh_radius_m", &o->fresh_radius_m);
  s.Read("fresh_collision_radius_m", &o->fresh_collision_radius_m);
  s.Read("validator_margin_m", &o->validator_margin_m);
  s.Read("stale_stop_s", &o->stale_stop_s);
  s.Read("stale_blind_distance_m", &o->stale_blind_distance_m);
  s.Read("stale_min_s", &o->stale_min_s);
  s.Finish();
}

void ReadTiming(YamlSection s, PlanTimingOptions* o) {
  s.Read("from_rest_time_limit_s", &o->from_rest_time_limit_s);
  s.Read("replan_budget_s", &o->replan_budget_s);
  s.Read("publish_margin_s", &o->publish_margin_s);
  s.Read("publish_collision_horizon_s", &o->publish_collision_horizon_s);
  s.Read("rest_speed", &o->rest_speed);
  s.Read("retry_period_s", &o->retry_period_s);
  s.Read("max_state_age_s", &o->max_state_age_s);
  s.Read("first_plan_attempts", &o->first_plan_attempts);
  s.Read("max_failed_plans_from_rest", &o->max_failed_plans_from_rest);
  s.Finish();
}

void ReadDelivery(YamlSection s, TrajectoryDeliveryOptions* o) {
  s.Read("resend_period_s", &o->resend_period_s);
  s.Read("give_up_s", &o->give_up_s);
  s.Finish();
}

void ReadTriggers(YamlSection s, ReplanTriggerOptions* o) {
  s.Read("check_sample_period_s", &o->check.sample_period_s);
  s.Read("check_obstacle_margin_m", &o->check.obstacle_margin_m);
  s.Read("drift_position_m", &o->drift_position_m);
  s.Read("drift_yaw_rad", &o->drift_yaw_rad);
  s.Read("drift_joint_rad", &o->drift_joint_rad);
  s.Read("drift_check_position_m", &o->drift_check.position_m);
  s.Read("drift_check_yaw_rad", &o->drift_check.yaw_rad);
  s.Read("drift_check_joint_rad", &o->drift_check.joint_rad);
  s.Read("drift_check_horizon_s", &o->drift_check.horizon_s);
  s.Read("drift_check_period_s", &o->drift_check.period_s);
  std::string drift_start = o->drift_start_tracked ? "tracked" : "carried";
  s.Read("drift_start", &drift_start);
  if (drift_start != "tracked" && drift_start != "carried") {
    throw ConfigError(s.source(), s.FieldPath("drift_start"), "expected tracked or carried, got '" + drift_start + "'");
  }
  o->drift_start_tracked = drift_start == "tracked";
  s.Read("check_reach_m", &o->check_reach_m);
  s.Finish();
}

void ReadStop(YamlSection s, SafeStopOptions* o) {
  s.Read("latency_s", &o->latency_s);
  s.Read("margin_s", &o->margin_s);
  s.Read("replan_grace_s", &o->replan_grace_s);
  s.Read("grace_reach_m", &o->grace_reach_m);
  s.Read("blind_duration_per_rate_ratio", &o->blind_duration_per_rate_ratio);
  s.Finish();
}

void ReadGoals(YamlSection s, GoalCheckOptions* o) {
  s.Read("target_clearance_m", &o->target_clearance_m);
  s.Read("unseen_pocket_reach_m", &o->unseen_pocket_reach_m);
  s.Read("unseen_pocket_rim_share", &o->unseen_pocket_rim_share);
  s.Read("certify_reachability", &o->certify_reachability);
  s.Read("reached_position_m", &o->reached_position_m);
  s.Read("reached_orientation_rad", &o->reached_orientation_rad);
  s.Finish();
}

void ReadLimits(YamlSection s, PlanLimitOptions* o) {
  s.Read("acceleration_share", &o->acceleration_share);
  s.Finish();
}

void ReadDeterministic(YamlSection s, DeterministicModeOptions* o) {
  s.Read("enabled", &o->enabled);
  s.Read("prm_samples", &o->prm_samples);
  int rrt_iterations = static_cast<int>(o->rrt_iterations);
  s.Read("rrt_iterations", &rrt_iterations);
  o->rrt_iterations = rrt_iterations;
  s.Read("time_limit_s", &o->time_limit_s);
  s.Finish();
}

void RequirePositive(double value, const std::string& source, const char* field) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw ConfigError(source, field, "must be finite and > 0, got " + std::to_string(value));
  }
}

void RequireNonNegative(double value, const std::string& source, const char* field) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw ConfigError(source, field, "must be finite and >= 0, got " + std::to_string(value));
  }
}

}  // namespace

std::optional<UnknownVoxelPolicy> ParseUnknownVoxelPolicy(const std::string& name) {
  if (name == "free") return UnknownVoxelPolicy::kFree;
  if (name == "occupied") return UnknownVoxelPolicy::kOccupied;
  if (name == "occupied_in_base_bands") return UnknownVoxelPolicy::kOccupiedInBaseBands;
  return std::nullopt;
}

const char* ToString(UnknownVoxelPolicy policy) {
  switch (policy) {
    case UnknownVoxelPolicy::kFree: return "free";
    case UnknownVoxelPolicy::kOccupied: return "occupied";
    case UnknownVoxelPolicy::kOccupiedInBaseBands: return "occupied_in_base_bands";
  }
  return "?";
}

void CheckPlannerProcessOptions(const PlannerProcessOptions& o, const std::string& source) {
  RequirePositive(o.map.field_update_period_s, source, "map.field_update_period_s");
  if (!(o.limits.acceleration_share > 0.0 && o.limits.acceleration_share <= 1.0)) {
    throw ConfigError(source, "limits.acceleration_share", "must be in (0, 1]");
  }
  RequirePositive(o.map.slice_m, source, "map.slice_m");
  RequirePositive(o.map.fresh_radius_m, source, "map.fresh_radius_m");
  RequirePositive(o.map.fresh_collision_radius_m, source, "map.fresh_collision_radius_m");
  RequireNonNegative(o.map.validator_margin_m, source, "map.validator_margin_m");
  RequireNonNegative(o.map.start_arm_overlap_m, source, "map.start_arm_overlap_m");
  if (o.map.start_arm_escape_overlap_m != 0.0 &&
      !(o.map.start_arm_escape_overlap_m >= o.map.start_arm_overlap_m && std::isfinite(o.map.start_arm_escape_overlap_m))) {
    throw ConfigError(source, "map.start_arm_escape_overlap_m", "must be 0 (no escape) or >= map.start_arm_overlap_m");
  }
  RequireNonNegative(o.map.stale_stop_s, source, "map.stale_stop_s");
  RequireNonNegative(o.map.stale_blind_distance_m, source, "map.stale_blind_distance_m");
  RequireNonNegative(o.map.stale_min_s, source, "map.stale_min_s");
  RequireNonNegative(o.delivery.resend_period_s, source, "delivery.resend_period_s");
  if (!(o.stop.blind_duration_per_rate_ratio >= 1.5) || !std::isfinite(o.stop.blind_duration_per_rate_ratio)) {
    throw ConfigError(source, "stop.blind_duration_per_rate_ratio", "must be finite and >= 1.5");
  }
  RequirePositive(o.delivery.give_up_s, source, "delivery.give_up_s");
  RequirePositive(o.timing.from_rest_time_limit_s, source, "timing.from_rest_time_limit_s");
  RequirePositive(o.timing.publish_margin_s, source, "timing.publish_margin_s");
  RequirePositive(o.timing.replan_budget_s - o.timing.publish_margin_s, source,
                  "timing.replan_budget_s (minus publish_margin_s)");
  RequirePositive(o.timing.publish_collision_horizon_s, source, "timing.publish_collision_horizon_s");
  RequirePositive(o.timing.rest_speed, source, "timing.rest_speed");
  RequirePositive(o.timing.retry_period_s, source, "timing.retry_period_s");
  RequirePositive(o.timing.max_state_age_s, source, "timing.max_state_age_s");
  if (o.timing.first_plan_attempts < 1) {
    throw ConfigError(source, "timing.first_plan_attempts", "must be >= 1");
  }
  if (o.timing.max_failed_plans_from_rest < 1) {
    throw ConfigError(source, "timing.max_failed_plans_from_rest", "must be >= 1");
  }
  RequirePositive(o.triggers.check.sample_period_s, source, "triggers.check_sample_period_s");
  RequireNonNegative(o.triggers.check.obstacle_margin_m, source, "triggers.check_obstacle_margin_m");
  RequirePositive(o.triggers.drift_position_m, source, "triggers.drift_position_m");
  RequirePositive(o.triggers.drift_yaw_rad, source, "triggers.drift_yaw_rad");
  RequirePositive(o.triggers.drift_joint_rad, source, "triggers.drift_joint_rad");
  RequirePositive(o.triggers.drift_check.position_m, source, "triggers.drift_check_position_m");
  RequirePositive(o.triggers.drift_check.yaw_rad, source, "triggers.drift_check_yaw_rad");
  RequirePositive(o.triggers.drift_check.joint_rad, source, "triggers.drift_check_joint_rad");
  RequirePositive(o.triggers.drift_check.horizon_s, source, "triggers.drift_check_horizon_s");
  RequirePositive(o.triggers.drift_check.period_s, source, "triggers.drift_check_period_s");
  RequirePositive(o.triggers.check_reach_m, source, "triggers.check_reach_m");
  RequireNonNegative(o.stop.latency_s, source, "stop.latency_s");
  RequireNonNegative(o.stop.margin_s, source, "stop.margin_s");
  RequirePositive(o.stop.replan_grace_s, source, "stop.replan_grace_s");
  RequireNonNegative(o.stop.grace_reach_m, source, "stop.grace_reach_m");
  RequireNonNegative(o.goals.target_clearance_m, source, "goals.target_clearance_m");
  RequireNonNegative(o.goals.unseen_pocket_reach_m, source, "goals.unseen_pocket_reach_m");
  if (!(o.goals.unseen_pocket_rim_share >= 0.0 && o.goals.unseen_pocket_rim_share <= 1.0)) {
    throw ConfigError(source, "goals.unseen_pocket_rim_share", "must lie in [0, 1]");
  }
  RequireNonNegative(o.goals.reached_position_m, source, "goals.reached_position_m");
  RequireNonNegative(o.goals.reached_orientation_rad, source, "goals.reached_orientation_rad");
  RequirePositive(o.status_period_s, source, "status_period_s");
  if (o.deterministic.prm_samples < 1) throw ConfigError(source, "deterministic.prm_samples", "must be >= 1");
  if (o.deterministic.rrt_iterations < 1) {
    throw ConfigError(source, "deterministic.rrt_iterations", "must be >= 1");
  }
  RequirePositive(o.deterministic.time_limit_s, source, "deterministic.time_limit_s");
}

void AdaptPlannerOptions(const PlannerProcessOptions& o, WholeBodyPlannerOptions* planner) {
  planner->validator.obstacle_margin_m += o.map.validator_margin_m;
  if (!o.deterministic.enabled) return;
  DeterministicBudgets budgets;
  budgets.prm_samples = o.deterministic.prm_samples;
  budgets.rrt_iterations = o.deterministic.rrt_iterations;
  planner->time_limit_s = o.deterministic.time_limit_s;  // first: MakeDeterministic bounds by it
  MakeDeterministic(planner, budgets);
}

void ApplyPlanLimits(const PlannerProcessOptions& o, RobotModel* model, WholeBodyPlannerOptions* planner) {
  const double share = o.limits.acceleration_share;
  if (!planner->base_limits) planner->base_limits = model->base_limits;
  for (BaseLimits* base : {&*planner->base_limits, &model->base_limits}) {
    base->a_max_mps2 *= share;
    base->beta_max_radps2 *= share;
  }
  model->joint_limits.qdd_max_radps2 *= share;
}

double FieldUpdatePeriod(const PlannerProcessOptions& o) {
  constexpr double kOnlyWhenAPlanAsks_s = 1e6;  // 11.6 days: in practice never by itself
  return o.deterministic.enabled ? kOnlyWhenAPlanAsks_s : o.map.field_update_period_s;
}

PlannerProcessOptions LoadPlannerProcessOptions(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  PlannerProcessOptions o;
  o.source = path;
  YamlSection top(root, path);
  ReadRobotFiles(&top, &o.robot_urdf, &o.robot_yaml);
  top.Read("planner_config", &o.planner_config);
  o.planner_config = ResolveBeside(o.planner_config, path);
  top.Read("tracker_config", &o.tracker_config);
  o.tracker_config = ResolveBeside(o.tracker_config, path);
  ReadMap(top.Section("map"), &o.map);
  ReadTiming(top.Section("timing"), &o.timing);
  ReadDelivery(top.Section("delivery"), &o.delivery);
  ReadTriggers(top.Section("triggers"), &o.triggers);
  ReadStop(top.Section("stop"), &o.stop);
  ReadGoals(top.Section("goals"), &o.goals);
  ReadLimits(top.Section("limits"), &o.limits);
  ReadDeterministic(top.Section("deterministic"), &o.deterministic);
  top.Read("status_period_s", &o.status_period_s);
  top.Finish();
  CheckPlannerProcessOptions(o, path);
  return o;
}

}  // namespace topay::planner
