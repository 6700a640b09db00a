#include "tools/topay_plan/planner_overrides.h"

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "tools/common/usage_error.h"

namespace topay::plan {
namespace {

RobotModel Model() {
  return LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                        TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
}

// What the YAML set, as LoadPlannerOptions would return it.
WholeBodyPlannerOptions Loaded() {
  WholeBodyPlannerOptions o;
  o.num_threads = 1;
  o.front_end.num_threads = 1;
  o.time_limit_s = 7.5;
  o.sequential = true;
  o.optimizer.time_limit_s = 1.25;
  o.front_end.acquisition_budget_s = 0.4;
  return o;
}

TEST(PlannerOverridesTest, UnsetOverridesKeepTheYamlValues) {
  WholeBodyPlannerOptions o = Loaded();
  const BaseLimitChoice choice = ApplyPlannerOverrides({}, Model(), &o);
  EXPECT_EQ(o.num_threads, 1);
  EXPECT_EQ(o.front_end.num_threads, 1);
  EXPECT_EQ(o.time_limit_s, 7.5);
  EXPECT_TRUE(o.sequential);
  EXPECT_EQ(o.optimizer.time_limit_s, 1.25);
  EXPECT_EQ(o.front_end.acquisition_budget_s, 0.4);
  // No limits in the YAML and no flag: the tools' default, the paper's benchmark limits.
  EXPECT_EQ(choice, BaseLimitChoice::kBenchmark);
  ASSERT_TRUE(o.base_limits.has_value());
  EXPECT_EQ(o.base_limits->omega_max_radps, BenchmarkBaseLimits().omega_max_radps);
}

TEST(PlannerOverridesTest, GivenOverridesWin) {
  WholeBodyPlannerOptions o = Loaded();
  PlannerOverrides flags;
  flags.num_threads = 2;
  flags.time_limit_s = 3.0;
  flags.sequential = false;
  flags.optimizer_time_limit_s = 0.5;
  flags.acquisition_budget_s = 0.2;
  flags.base_limits = BaseLimitChoice::kRobot;
  const RobotModel model = Model();
  EXPECT_EQ(ApplyPlannerOverrides(flags, model, &o), BaseLimitChoice::kRobot);
  EXPECT_EQ(o.num_threads, 2);
  EXPECT_EQ(o.front_end.num_threads, 2);
  EXPECT_EQ(o.time_limit_s, 3.0);
  EXPECT_FALSE(o.sequential);
  EXPECT_EQ(o.optimizer.time_limit_s, 0.5);
  EXPECT_EQ(o.front_end.acquisition_budget_s, 0.2);
  EXPECT_EQ(o.base_limits->omega_max_radps, model.base_limits.omega_max_radps);
}

TEST(PlannerOverridesTest, YamlBaseLimitsHoldUnlessTheFlagIsGiven) {
  BaseLimits configured;
  configured.v_max_mps = 0.7;
  configured.a_max_mps2 = 0.5;
  configured.omega_max_radps = 0.6;
  configured.beta_max_radps2 = 0.9;
  WholeBodyPlannerOptions o = Loaded();
  o.base_limits = configured;
  EXPECT_EQ(ApplyPlannerOverrides({}, Model(), &o), BaseLimitChoice::kConfig);
  EXPECT_EQ(o.base_limits->v_max_mps, 0.7);

  o.base_limits = configured;
  PlannerOverrides flags;
  flags.base_limits = BaseLimitChoice::kBenchmark;
  EXPECT_EQ(ApplyPlannerOverrides(flags, Model(), &o), BaseLimitChoice::kBenchmark);
  EXPECT_EQ(o.base_limits->v_max_mps, BenchmarkBaseLimits().v_max_mps);
}

TEST(PlannerOverridesTest, ConfigChoiceWithoutYamlLimitsIsAnError) {
  WholeBodyPlannerOptions o = Loaded();
  PlannerOverrides flags;
  flags.base_limits = BaseLimitChoice::kConfig;
  EXPECT_THROW(ApplyPlannerOverrides(flags, Model(), &o), tools::UsageError);
}

}  // namespace
}  // namespace topay::plan
