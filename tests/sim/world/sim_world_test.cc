// The simulated world (sim/world/): stable ids, presence, versions; the scene sources.

#include "sim/world/sim_world.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "sim/scenes/scene_json.h"
#include "sim/world/scene_source.h"

namespace topay::sim {
namespace {

TEST(SimWorld, KeepsStableIdsWhileBoxesComeAndGo) {
  Scene scene;
  for (int i = 0; i < 4; ++i) {
    OrientedBox b;
    b.center_W_m.x() = i;
    scene.boxes.push_back(b);
  }
  SimWorld world(scene);
  EXPECT_EQ(world.num_present(), 4);
  const std::int64_t v0 = world.version();
  std::string error;
  ASSERT_TRUE(world.Disappear(1, &error));
  EXPECT_GT(world.version(), v0);
  EXPECT_EQ(world.present_ids(), (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(world.present_boxes()[1].center_W_m.x(), 2.0);  // box 2 keeps its geometry and id
  EXPECT_EQ(world.IdOfPresentIndex(1), 2);
  EXPECT_EQ(world.IdOfPresentIndex(3), -1);
  const std::int64_t v1 = world.version();
  ASSERT_TRUE(world.Disappear(1, &error));  // already gone: no change
  EXPECT_EQ(world.version(), v1);
  EXPECT_FALSE(world.Disappear(9, &error));
  EXPECT_NE(error.find("box 9 does not exist"), std::string::npos);
  OrientedBox bad;
  bad.size_m.y() = 0.0;
  EXPECT_FALSE(world.Appear(20, bad, &error));
  EXPECT_NE(error.find("> 0"), std::string::npos);
  EXPECT_FALSE(world.Appear(-1, std::nullopt, &error));
  EXPECT_EQ(world.num_boxes(), 4);
}

TEST(SceneSource, ParsesTheSceneArgument) {
  EXPECT_FALSE(ParseSceneArgument("", 1).has_value());
  const auto tables = ParseSceneArgument("tables", 9);
  ASSERT_TRUE(tables && tables->kind);
  EXPECT_EQ(*tables->kind, SceneKind::kTables);
  EXPECT_EQ(tables->seed, 9u);
  const auto file = ParseSceneArgument("room.json", 9);
  ASSERT_TRUE(file);
  EXPECT_FALSE(file->kind.has_value());
  EXPECT_EQ(file->file, "room.json");
}

TEST(SceneSource, GeneratesTheBenchmarkRoomAndKeepsTheStartClear) {
  KeepOutRegions keep_out;
  VerticalCylinder start;
  start.radius_m = 1.0;
  start.height_m = 2.0;
  keep_out.cylinders.push_back(start);
  const Scene a = LoadScene(*ParseSceneArgument("cuboids", 3), keep_out);
  const Scene b = LoadScene(*ParseSceneArgument("cuboids", 3), keep_out);
  EXPECT_EQ(a.boxes.size(), 164u);  // 4 walls + 80 grounded + 80 floating
  EXPECT_EQ(SceneToJson(a), SceneToJson(b));
  for (std::size_t i = 4; i < a.boxes.size(); ++i) {
    EXPECT_GT(SignedDistanceToFootprint(a.boxes[i], Eigen::Vector2d::Zero()), 1.0 - 1e-9) << i;
  }
}

TEST(SceneSource, MalformedSceneFileIsAConfigError) {
  const std::string path = std::string(TOPAY_BINARY_DIR) + "/test_out/sim_world_bad_scene.json";
  std::filesystem::create_directories(std::string(TOPAY_BINARY_DIR) + "/test_out");
  std::ofstream(path) << R"({"boxes": [{"center": [0, 0], "size": [1, 1, 1], "yaw": 0}]})";
  try {
    LoadScene(*ParseSceneArgument(path, 1));
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(e.field().find("boxes[0].center"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::sim
