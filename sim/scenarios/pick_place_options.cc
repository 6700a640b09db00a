#include "sim/scenarios/pick_place_options.h"

#include <cmath>
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
  RequireAtLeast(o.height_min_m, 0.0, source, "height_min_m");
  RequireAtLeast(o.height_max_m, o.height_min_m, source, "height_max_m");
  RequireAtLeast(o.edge_inset_m, 0.0, source, "edge_inset_m");
  RequireAtLeast(o.obstacle_clearance_m, 0.0, source, "obstacle_clearance_m");
  RequireAtLeast(o.pickup_distance_min_m, 0.0, source, "pickup_distance_min_m");
  RequireAtLeast(o.dropoff_distance_min_m, 0.0, source, "dropoff_distance_min_m");
  RequirePositive(o.max_targets, source, "max_targets");
  RequirePositive(o.max_pickups, source, "max_pickups");
  RequirePositive(o.ik_iterations, source, "ik_iterations");
  RequireAtLeast(o.wait_s, 0.0, source, "wait_s");
}

PickPlaceScenarioOptions LoadPickPlaceScenarioOptions(const std::string& path) {
  PickPlaceScenarioOptions o;
  o.source = path;
  YamlSection top(LoadYamlFile(path), path);
  top.Read("keep_out_radius_m", &o.keep_out_radius_m);
  top.Read("height_min_m", &o.height_min_m);
  top.Read("height_max_m", &o.height_max_m);
  top.Read("edge_inset_m", &o.edge_inset_m);
  top.Read("obstacle_clearance_m", &o.obstacle_clearance_m);
  top.Read("pickup_distance_min_m", &o.pickup_distance_min_m);
  top.Read("dropoff_distance_min_m", &o.dropoff_distance_min_m);
  top.Read("tool_down", &o.tool_down);
  top.Read("max_targets", &o.max_targets);
  top.Read("max_pickups", &o.max_pickups);
  top.Read("ik_iterations", &o.ik_iterations);
  top.Read("wait_s", &o.wait_s);
  top.Finish();
  CheckPickPlaceScenarioOptions(o, path);
  return o;
}

}  // namespace topay
