// topay-director's script: the shipped file loads; bad keys, types and values are rejected
// naming the file and the field.

#include "procs/director/director_options.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "tests/common/temp_path.h"

namespace topay::director {
namespace {

std::string Write(const std::string& text) {
  const std::string path = UniqueTempPath("director.yaml");
  std::ofstream(path) << text;
  return path;
}

std::string ErrorOf(const std::string& text) {
  try {
    LoadDirectorOptions(Write(text));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

constexpr const char* kEvent = "events:\n  - type: box_on_route\n    during_step: dropoff\n";

TEST(DirectorOptions, ShippedScriptPutsOneBoxOnTheWayToTheDropoff) {
  const DirectorOptions o = LoadDirectorOptions(std::string(TOPAY_SOURCE_DIR) + "/config/director/pick_place.yaml");
  ASSERT_EQ(o.events.size(), 1u);
  const BoxOnRouteEvent& e = o.events[0];
  EXPECT_EQ(e.during_step, "dropoff");
  EXPECT_EQ(e.min_speed_mps, 0.3);
  EXPECT_EQ(e.box.ahead_min_m, 2.5);
  EXPECT_EQ(e.box.ahead_max_m, 3.5);
  EXPECT_EQ(e.box.side_min_m, 0.4);
  EXPECT_EQ(e.box.side_max_m, 0.6);
  EXPECT_EQ(e.box.height_m, 1.0);
  EXPECT_EQ(e.box_id, -1);
  const RouteBoxOptions d;
  EXPECT_EQ(e.box.min_robot_distance_m, d.min_robot_distance_m);
  EXPECT_EQ(e.box.scene_gap_m, d.scene_gap_m);
  EXPECT_EQ(e.box.end_margin_m, d.end_margin_m);
  EXPECT_EQ(e.box.tries, d.tries);
  EXPECT_EQ(o.seed, 1u);
  EXPECT_EQ(o.tick_period_s, DirectorOptions{}.tick_period_s);
  EXPECT_EQ(o.retry_period_s, DirectorOptions{}.retry_period_s);
}

TEST(DirectorOptions, EventDefaultsAndFields) {
  const DirectorOptions o = LoadDirectorOptions(
      Write(std::string(kEvent) + "    ahead_m: [3, 4]\n    box_id: 77\n    name: crate\nseed: 9\n"));
  ASSERT_EQ(o.events.size(), 1u);
  EXPECT_EQ(o.events[0].box.ahead_min_m, 3.0);
  EXPECT_EQ(o.events[0].box.ahead_max_m, 4.0);
  EXPECT_EQ(o.events[0].box_id, 77);
  EXPECT_EQ(o.events[0].name, "crate");
  EXPECT_EQ(o.seed, 9u);
  EXPECT_EQ(LoadDirectorOptions(Write("retry_period_s: 2.5\n")).retry_period_s, 2.5);
  EXPECT_TRUE(LoadDirectorOptions(Write("seed: 2\n")).events.empty());
}

TEST(DirectorOptions, BadScriptsNameTheField) {
  EXPECT_NE(ErrorOf("sede: 1\n").find("sede"), std::string::npos);
  EXPECT_NE(ErrorOf("tick_period_s: 0\n").find("tick_period_s"), std::string::npos);
  EXPECT_NE(ErrorOf("retry_period_s: -1\n").find("retry_period_s"), std::string::npos);
  EXPECT_NE(ErrorOf("retry_period_s: .nan\n").find("retry_period_s"), std::string::npos);
  EXPECT_NE(ErrorOf("events: 3\n").find("events"), std::string::npos);
  EXPECT_NE(ErrorOf("events:\n  - type: box_flood\n    during_step: x\n").find("events[0].type"), std::string::npos);
  EXPECT_NE(ErrorOf("events:\n  - type: box_on_route\n").find("events[0].during_step"), std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kEvent) + "    ahead: [1, 2]\n").find("events[0].ahead"), std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kEvent) + "    ahead_m: [4, 3]\n").find("events[0].ahead_m"), std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kEvent) + "    side_m: [0.4]\n").find("events[0].side_m"), std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kEvent) + "    height_m: -1\n").find("height_m"), std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kEvent) + "    min_speed_mps: fast\n").find("events[0].min_speed_mps"),
            std::string::npos);
  EXPECT_NE(ErrorOf(std::string(kEvent) + "    box_id: -5\n").find("events[0].box_id"), std::string::npos);
  EXPECT_EQ(ErrorOf(kEvent), "");
}

}  // namespace
}  // namespace topay::director
