// The pick-and-place scenario's options: the shipped file holds the defaults; bad keys and
// values are rejected naming the file and the key.

#include "sim/scenarios/pick_place_options.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/common/error.h"
#include "tests/common/temp_path.h"

namespace topay {
namespace {

std::string Write(const std::string& text) {
  const std::string path = UniqueTempPath("pick_place.yaml");
  std::ofstream(path) << text;
  return path;
}

// The ConfigError's message for `text`, "" if it loads.
std::string ErrorOf(const std::string& text) {
  try {
    LoadPickPlaceScenarioOptions(Write(text));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(PickPlaceOptions, ShippedFileHoldsTheDefaults) {
  const PickPlaceScenarioOptions o =
      LoadPickPlaceScenarioOptions(std::string(TOPAY_SOURCE_DIR) + "/config/scenarios/pick_place.yaml");
  const PickPlaceScenarioOptions d;
  EXPECT_EQ(o.keep_out_radius_m, d.keep_out_radius_m);
  EXPECT_EQ(o.top_height_max_m, d.top_height_max_m);
  EXPECT_EQ(o.height_min_m, d.height_min_m);
  EXPECT_EQ(o.height_max_m, d.height_max_m);
  EXPECT_EQ(o.edge_inset_m, d.edge_inset_m);
  EXPECT_EQ(o.edge_depth_max_m, d.edge_depth_max_m);
  EXPECT_EQ(o.tool_yaw_spread_rad, d.tool_yaw_spread_rad);
  EXPECT_EQ(o.tool_pitch_min_rad, d.tool_pitch_min_rad);
  EXPECT_EQ(o.tool_pitch_max_rad, d.tool_pitch_max_rad);
  EXPECT_EQ(o.obstacle_clearance_m, d.obstacle_clearance_m);
  EXPECT_EQ(o.pickup_distance_min_m, d.pickup_distance_min_m);
  EXPECT_EQ(o.dropoff_distance_min_m, d.dropoff_distance_min_m);
  EXPECT_EQ(o.max_targets, d.max_targets);
  EXPECT_EQ(o.max_pickups, d.max_pickups);
  EXPECT_EQ(o.ik_iterations, d.ik_iterations);
  EXPECT_EQ(o.ik_base_candidates, d.ik_base_candidates);
  EXPECT_EQ(o.wait_s, d.wait_s);
}

TEST(PickPlaceOptions, ReadsKeys) {
  const PickPlaceScenarioOptions o = LoadPickPlaceScenarioOptions(Write("dropoff_distance_min_m: 5.5\nmax_pickups: 2\n"));
  EXPECT_EQ(o.dropoff_distance_min_m, 5.5);
  EXPECT_EQ(o.max_pickups, 2);
}

TEST(PickPlaceOptions, BadKeysAndValuesNameTheKey) {
  EXPECT_NE(ErrorOf("dropof_distance_min_m: 4\n").find("dropof_distance_min_m"), std::string::npos);
  EXPECT_NE(ErrorOf("height_min_m: -0.1\n").find("height_min_m"), std::string::npos);
  EXPECT_NE(ErrorOf("height_min_m: 0.3\nheight_max_m: 0.2\n").find("height_max_m"), std::string::npos);
  EXPECT_NE(ErrorOf("max_targets: 0\n").find("max_targets"), std::string::npos);
  EXPECT_NE(ErrorOf("tool_pitch_max_rad: 2.0\n").find("tool_pitch_max_rad"), std::string::npos);
  EXPECT_NE(ErrorOf("obstacle_clearance_m: high\n").find("obstacle_clearance_m"), std::string::npos);
  EXPECT_NE(ErrorOf("wait_s: .nan\n").find("wait_s"), std::string::npos);
  EXPECT_EQ(ErrorOf("max_targets: 10\n"), "");
}

}  // namespace
}  // namespace topay
