// Runs the built topay-scene binary end to end in a temporary folder.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "sim/scenes/scene_json.h"
#include "sim/scenes/task_json.h"
#include "tools/viz/png_io.h"
#include "tools/viz/scene_renderer.h"
#include "tests/common/tool_test.h"

namespace topay {
namespace {

namespace fs = std::filesystem;

class TopaySceneTest : public ToolTest {
 protected:
  TopaySceneTest() : ToolTest("topay-scene") {}

};

TEST_F(TopaySceneTest, GeneratesSceneTaskAndPng) {
  const RunResult run = Run("--scene cuboids --seed 3 --range small --px-per-m 10 --json '" +
                            Path("scene.json") + "' --task-json '" + Path("task.json") +
                            "' --png '" + Path("scene.png") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("boxes"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("base distance"), std::string::npos) << run.out;

  const viz::Image png = viz::ReadPng(Path("scene.png"));
  // The map covers the 20 x 20 m room plus 0.25 m margins at 10 px/m, right of the y axis;
  // the legend lies below.
  EXPECT_EQ(png.width(), viz::SceneImageWidth(205));
  EXPECT_GT(png.height(), 205);

  const Scene scene = ReadSceneJson(Path("scene.json"));
  EXPECT_EQ(scene.kind, "cuboids");
  EXPECT_EQ(scene.boxes.size(), 4u + 80u + 80u);
  const PlanningTask task = ReadTaskJson(Path("task.json"));
  EXPECT_EQ(task.range, DistanceRange::kSmall);
  EXPECT_EQ(task.seed, 3u);
  EXPECT_TRUE(DistanceRangeBounds(DistanceRange::kSmall).Contains(task.base_distance_m));
}

TEST_F(TopaySceneTest, SceneAndTaskFilesRoundTripToIdenticalJson) {
  ASSERT_EQ(Run("--scene tables --seed 5 --range medium --json '" + Path("a.json") +
                "' --task-json '" + Path("a_task.json") + "'")
                .exit_code,
            0);
  const RunResult run = Run("--scene-file '" + Path("a.json") + "' --task-file '" +
                            Path("a_task.json") + "' --json '" + Path("b.json") +
                            "' --task-json '" + Path("b_task.json") + "' --px-per-m 5 --png '" +
                            Path("b.png") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(ReadText(Path("a.json")), ReadText(Path("b.json")));
  EXPECT_FALSE(ReadText(Path("a.json")).empty());
  // The task survives the round trip. (Its bytes may differ in the last digits of the goal
  // quaternion: sim/scenes/task_json stores X_WE_goal as a rotation matrix, and matrix ->
  // quaternion is not bit-exact. Start, goal and distance are compared exactly.)
  const PlanningTask a = ReadTaskJson(Path("a_task.json"));
  const PlanningTask b = ReadTaskJson(Path("b_task.json"));
  EXPECT_EQ(a.start.ToVector(), b.start.ToVector());
  EXPECT_EQ(a.goal.ToVector(), b.goal.ToVector());
  EXPECT_EQ(a.base_distance_m, b.base_distance_m);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.scene_seed, b.scene_seed);
  EXPECT_TRUE(a.X_WE_goal.isApprox(b.X_WE_goal, 1e-14));
  EXPECT_TRUE(fs::exists(Path("b.png")));
}

TEST_F(TopaySceneTest, MissingSceneFileIsNamed) {
  const std::string missing = Path("no_such_scene.json");
  const RunResult run = Run("--scene-file '" + missing + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;
}

TEST_F(TopaySceneTest, MalformedSceneJsonIsNamed) {
  const std::string bad = Path("bad.json");
  std::ofstream(bad) << "{\"boxes\": [ {\"center\": [1, 2, 3], ";
  const RunResult run = Run("--scene-file '" + bad + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find(bad), std::string::npos) << run.err;
}

TEST_F(TopaySceneTest, MalformedTaskJsonIsNamed) {
  const std::string bad = Path("bad_task.json");
  std::ofstream(bad) << "{\"range\": \"huge\"}";
  const RunResult run = Run("--scene cuboids --task-file '" + bad + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find(bad), std::string::npos) << run.err;
}

TEST_F(TopaySceneTest, UnknownSceneKindAndRangeAreNamed) {
  RunResult run = Run("--scene forest");
  EXPECT_EQ(run.exit_code, 2);  // usage errors exit 2, as in every tool
  EXPECT_NE(run.err.find("--scene"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("forest"), std::string::npos) << run.err;
  run = Run("--scene tables --range huge");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("huge"), std::string::npos) << run.err;
}

TEST_F(TopaySceneTest, MissingRobotFilesAreNamed) {
  const std::string urdf = Path("missing_robot.urdf");
  RunResult run = Run("--scene cuboids --robot '" + urdf + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find(urdf), std::string::npos) << run.err;
  // The config folder comes from TOPAY_CONFIG_DIR when it is set.
  run = Run("--scene cuboids", "TOPAY_CONFIG_DIR='" + dir_.string() + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find(dir_.string() + "/robot/topay_mm.urdf"), std::string::npos) << run.err;
}

TEST_F(TopaySceneTest, BadFlagValuesAndUnwritableOutputsAreReported) {
  RunResult run = Run("--scene cuboids --resolution -1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--resolution"), std::string::npos) << run.err;
  run = Run("--scene cuboids --resolution abc");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--resolution"), std::string::npos) << run.err;
  run = Run("--scene cuboids --scene-file x.json");
  EXPECT_EQ(run.exit_code, 2);
  run = Run("");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--scene"), std::string::npos) << run.err;
  run = Run("--scene cuboids --seed -1");  // would wrap to 2^64 - 1
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--seed"), std::string::npos) << run.err;
  run = Run("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("Exit codes: 0 success, 1 file or configuration error, 2 usage error"),
            std::string::npos)
      << run.out;
  const std::string png = Path("no_such_folder/out.png");
  run = Run("--scene cuboids --png '" + png + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find(png), std::string::npos) << run.err;
}

}  // namespace
}  // namespace topay
