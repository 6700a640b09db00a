#include "tools/topay_bench/bench_task.h"

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/planner/whole_body_planner_options.h"

namespace topay::bench {
namespace {

TEST(BenchTaskTest, FileNamesHaveFourDigitIndices) {
  EXPECT_EQ(TaskFilePath("out", 7, "scene.json"), "out/task_0007_scene.json");
  EXPECT_EQ(TaskFilePath("/a/b", 12345, "topay_trajectory.json"),
            "/a/b/task_12345_topay_trajectory.json");
}

TEST(BenchTaskTest, RunsEveryMethodInRotationOnTheSameTask) {
  const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                          TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  const WholeBodyPlannerOptions loaded;
  BenchTaskContext context;
  context.kinematics = &kinematics;
  context.loaded_options = &loaded;
  context.settings.base_limits = model.base_limits;
  context.settings.num_threads = 1;
  context.settings.time_limit_ms = 60000.0;
  context.range = DistanceRange::kSmall;
  context.seed = 3;
  context.methods = {BenchMethod::kTopay, BenchMethod::kFlatness};

  // Task 1 of 2 methods starts with method 1 mod 2 = flatness.
  const std::vector<BenchRecord> records = RunBenchTask(context, 1);
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].method, "flatness");
  EXPECT_EQ(records[1].method, "topay");
  for (int k = 0; k < 2; ++k) {
    const BenchRecord& r = records[k];
    EXPECT_EQ(r.order, k);
    EXPECT_EQ(r.task, 1);
    EXPECT_EQ(r.task_seed, DeriveSeed(3, 1));
    EXPECT_EQ(r.scene, "cuboids");
    EXPECT_EQ(r.range, "small");
    EXPECT_TRUE(r.used_hint);
    EXPECT_GT(r.base_distance_m, 0.0);
    EXPECT_GT(r.map_ms, 0.0);
    EXPECT_FALSE(r.status.empty());
    EXPECT_EQ(r.success, r.status == "success");
    EXPECT_EQ(r.success, r.failure_reason.empty()) << r.failure_reason;
    EXPECT_EQ(r.success, r.validation.has_value() && r.validation->ok);
  }
  // Identical task for both methods, one map for both.
  EXPECT_EQ(records[0].scene_seed, records[1].scene_seed);
  EXPECT_EQ(records[0].start.ToVector(), records[1].start.ToVector());
  EXPECT_EQ(records[0].X_WE_goal.matrix(), records[1].X_WE_goal.matrix());
  EXPECT_EQ(records[0].map_ms, records[1].map_ms);
}

}  // namespace
}  // namespace topay::bench
