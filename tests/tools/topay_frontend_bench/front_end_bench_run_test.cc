#include "tools/topay_frontend_bench/front_end_bench_run.h"

#include <sstream>

#include <gtest/gtest.h>

#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"

namespace topay::frontend_bench {
namespace {

class FrontEndBenchRunTest : public ::testing::Test {
 protected:
  FrontEndBenchRunTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        configured_(LoadPlannerOptions(TOPAY_SOURCE_DIR "/config/planner/topay.yaml").front_end) {}
  RobotModel model_;
  Kinematics kinematics_;
  FrontEndOptions configured_;
};

TEST_F(FrontEndBenchRunTest, OverridesApplyOnlyWhenGiven) {
  FrontEndBenchOptions o;
  const FrontEndOptions unchanged = TaskFrontEndOptions(o, configured_, 0, kinematics_);
  EXPECT_EQ(unchanged.rrt.time_budget_s, configured_.rrt.time_budget_s);
  EXPECT_EQ(unchanged.improvement_window_s, configured_.improvement_window_s);
  EXPECT_EQ(unchanged.topology.mode, configured_.topology.mode);
  EXPECT_EQ(unchanged.num_threads, configured_.num_threads);
  ASSERT_TRUE(unchanged.base_limits.has_value());
  EXPECT_EQ(unchanged.base_limits->omega_max_radps, 1.25);  // no YAML limits: the benchmark's
  FrontEndOptions with_limits = configured_;
  BaseLimits yaml_limits = model_.base_limits;
  yaml_limits.omega_max_radps = 0.55;
  with_limits.base_limits = yaml_limits;
  EXPECT_EQ(TaskFrontEndOptions(o, with_limits, 0, kinematics_).base_limits->omega_max_radps, 0.55);
  o.rrt_budget_s = 0.123;
  o.window_s = 0.0;
  o.jps_only = true;
  o.omega_max_radps = 0.7;
  o.threads = 1;
  const FrontEndOptions changed = TaskFrontEndOptions(o, configured_, 0, kinematics_);
  EXPECT_EQ(changed.rrt.time_budget_s, 0.123);
  EXPECT_EQ(changed.improvement_window_s, 0.0);
  EXPECT_EQ(changed.topology.mode, BasePathMode::kJpsOnly);
  EXPECT_EQ(changed.num_threads, 1);
  ASSERT_TRUE(changed.base_limits.has_value());
  EXPECT_EQ(changed.base_limits->omega_max_radps, 0.7);
  // Each task has its own seed.
  EXPECT_NE(TaskFrontEndOptions(o, configured_, 1, kinematics_).seed, changed.seed);
}

TEST_F(FrontEndBenchRunTest, SmallCuboidsTasksGetExactlyCheckedPaths) {
  FrontEndBenchOptions o;
  o.threads = 1;
  o.verbose = true;
  FrontEndTally tally;
  std::ostringstream log;
  for (int i = 0; i < 3; ++i) {
    RunFrontEndTask(o, configured_, SceneKind::kCuboids, DistanceRange::kSmall, i, kinematics_,
                    &tally, log);
  }
  EXPECT_EQ(tally.tasks, 3);
  EXPECT_EQ(tally.paths_failing_exact_check, 0);
  // Cuboids small: the front end finds a path on every task (measured 100 %, benchmarks.md).
  EXPECT_EQ(tally.tasks_ok, 3) << log.str();
  EXPECT_NE(log.str().find("task 2:"), std::string::npos);
}

}  // namespace
}  // namespace topay::frontend_bench
