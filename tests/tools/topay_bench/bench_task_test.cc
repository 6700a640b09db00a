#include "tools/topay_bench/bench_task.h"

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/planner/whole_body_planner_options.h"
#include "sim/scenes/task_generator.h"

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

TEST(BenchTaskTest, ATightTaskCarriesItsEndsAndAFailureCategory) {
  const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                          TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  const WholeBodyPlannerOptions loaded;
  BenchTaskContext context;
  context.kinematics = &kinematics;
  context.loaded_options = &loaded;
  context.settings.base_limits = model.base_limits;
  context.settings.num_threads = 1;
  context.settings.time_limit_ms = 3000.0;
  context.kind = SceneKind::kTables;
  context.range = DistanceRange::kSmall;
  context.generator.tightness = TaskTightness::kTight;
  context.seed = 5;
  context.methods = {BenchMethod::kTopay};
  const std::vector<BenchRecord> records = RunBenchTask(context, 0);
  ASSERT_EQ(records.size(), 1u);
  const BenchRecord& r = records[0];
  EXPECT_TRUE(r.tight);
  EXPECT_EQ(r.cell(), "tables small tight");
  // The same task as the generator makes for the task seed.
  const BenchmarkCase expected = GenerateBenchmarkCase(
      SceneKind::kTables, DistanceRange::kSmall, DeriveSeed(5, 0), kinematics, context.generator);
  ASSERT_TRUE(r.tight_info.has_value());
  EXPECT_EQ(r.tight_info->start.clearance_m, expected.task.tight->start.clearance_m);
  EXPECT_EQ(r.tight_info->goal.box, expected.task.tight->goal.box);
  EXPECT_EQ(r.start.ToVector(), expected.task.start.ToVector());
  EXPECT_EQ(r.success, r.failure == FailureCategory::kNone) << r.failure_reason;
  if (!r.success) {
    EXPECT_FALSE(r.failure_reason.empty());
  }
}

}  // namespace
}  // namespace topay::bench
