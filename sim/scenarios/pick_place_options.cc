#include "sim/scenarios/pick_place_options.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay {
namespace {

void RequireAtLeast(double value, double low, const std::string& source, const char* key) {
  if (!(std::isfinite(value) && value >= low)) {
    throw ConfigError(source, key, "must be finite and >= " + std::to_string(low) + ", got " + std::to_string(value));
  }
}

void RequirePositive(int value, const std::string& source, const char* key) {
  if (value < 1) throw ConfigError(source, key, "must be >= 1, got " + std::to_string(value));
}

}  // namespace

void CheckPickPlaceScenarioOptions(const PickPlaceScenarioOptions& o, const std::string& source) {
  RequireAtLeast(o.keep_out_radius_m, 0.0, source, "keep_out_radius_m");
  RequireAtLeast(o.top_height_max_m, 0.0, source, "top_height_max_m");
  RequireAtLeast(o.height_min_m, 0.0, source, "height_min_m");
  RequireAtLeast(o.height_max_m, o.height_min_m, source, "height_max_m");
  RequireAtLeast(o.edge_inset_m, 0.0, source, "edge_inset_m");
  RequireAtLeast(o.edge_depth_max_m, o.edge_inset_m, source, "edge_depth_max_m");
  RequireAtLeast(o.tool_yaw_spread_rad, 0.0, source, "tool_yaw_spread_rad");
  RequireAtLeast(o.tool_pitch_min_rad, -0.5 * std::numbers::pi, source, "tool_pitch_min_rad");
  RequireAtLeast(o.tool_pitch_max_rad, o.tool_pitch_min_rad, source, "tool_pitch_max_rad");
  if (o.tool_pitch_max_rad > 0.5 * std::numbers::pi + 1e-9) {
    throw ConfigError(source, "tool_pitch_max_rad", "must be <= pi/2, got " + std::to_string(o.tool_pitch_max_rad));
  }
  RequireAtLeast(o.obstacle_clearance_m, 0.0, source, "obstacle_clearance_m");
  RequireAtLeast(o.pickup_distance_min_m, 0.0, source, "pickup_distance_min_m");
  RequireAtLeast(o.dropoff_distance_min_m, 0.0, source, "dropoff_distance_min_m");
  RequirePositive(o.max_targets, source, "max_targets");
  RequirePositive(o.max_pickups, source, "max_pickups");
  RequirePositive(o.ik_iterations, source, "ik_iterations");
  RequirePositive(o.ik_base_candidates, source, "ik_base_candidates");
  RequireAtLeast(o.wait_s, 0.0, source, "wait_s");
}

PickPlaceScenarioOptions LoadPickPlaceScenarioOptions(const std::string& path) {
  PickPlaceScenarioOptions o;
  o.source = path;
  YamlSection top(LoadYamlFile(path), path);
  top.Read("keep_out_radius_m", &o.keep_out_radius_m);
  top.Read("top_height_max_m", &o.top_height_max_m);
  top.Read("height_min_m", &o.height_min_m);
  top.Read("height_max_m", &o.height_max_m);
  top.Read("edge_inset_m", &o.edge_inset_m);
  top.Read("obstacle_clearance_m", &o.obstacle_clearance_m);
  top.Read("pickup_distance_min_m", &o.pickup_distance_min_m);
  top.Read("dropoff_distance_min_m", &o.dropoff_distance_min_m);
  top.Read("edge_depth_max_m", &o.edge_depth_max_m);
  top.Read("tool_yaw_spread_rad", &o.tool_yaw_spread_rad);
  top.Read("tool_pitch_min_rad", &o.tool_pitch_min_rad);
  top.Read("tool_pitch_max_rad", &o.tool_pitch_max_rad);
  top.Read("ik_base_candidates", &o.ik_base_candidates);
  top.Read("max_targets", &o.max_targets);
  top.Read("max_pickups", &o.max_pickups);
  top.Read("ik_iterations", &o.ik_iterations);
  top.Read("wait_s", &o.wait_s);
  top.Finish();
  CheckPickPlaceScenarioOptions(o, path);
  return o;
}

}  // namespace topay
