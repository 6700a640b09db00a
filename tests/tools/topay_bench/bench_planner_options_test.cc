#include "tools/topay_bench/bench_planner_options.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/random.h"

namespace topay::bench {
namespace {

BenchPlannerSettings Settings(int threads) {
  BenchPlannerSettings s;
  s.base_limits.omega_max_radps = 1.25;
  s.num_threads = threads;
  s.time_limit_ms = 2500.0;
  return s;
}

TEST(BenchPlannerOptionsTest, SetsThreadsTimeLimitLimitsAndTaskSeeds) {
  WholeBodyPlannerOptions loaded;
  loaded.num_threads = 0;
  loaded.front_end.num_threads = 0;
  const WholeBodyPlannerOptions o =
      BenchPlannerOptions(loaded, BenchMethod::kTopay, Settings(2), 77);
  EXPECT_EQ(o.num_threads, 2);
  EXPECT_EQ(o.front_end.num_threads, 2);
  EXPECT_DOUBLE_EQ(o.time_limit_s, 2.5);
  ASSERT_TRUE(o.base_limits.has_value());
  EXPECT_DOUBLE_EQ(o.base_limits->omega_max_radps, 1.25);
  EXPECT_EQ(o.front_end.seed, DeriveSeed(77, 1000));
  EXPECT_EQ(o.front_end.ik.seed, DeriveSeed(77, 1001));
  // Wall-clock budgets stay with more than one thread.
  EXPECT_DOUBLE_EQ(o.front_end.rrt.time_budget_s, loaded.front_end.rrt.time_budget_s);
}

TEST(BenchPlannerOptionsTest, AppliesTheMethod) {
  const WholeBodyPlannerOptions o = BenchPlannerOptions({}, BenchMethod::kFlatness, Settings(2), 1);
  EXPECT_EQ(o.optimizer.parameterisation, TrajectoryParameterisation::kFlatness);
  EXPECT_EQ(o.max_candidates, 1);
}

TEST(BenchPlannerOptionsTest, OneThreadIsDeterministic) {
  const WholeBodyPlannerOptions o = BenchPlannerOptions({}, BenchMethod::kTopay, Settings(1), 1);
  EXPECT_EQ(o.num_threads, 1);
  EXPECT_EQ(o.front_end.num_threads, 1);
  // MakeDeterministic replaces the wall-clock budgets by work budgets.
  EXPECT_TRUE(std::isinf(o.front_end.rrt.time_budget_s));
  EXPECT_TRUE(std::isinf(o.front_end.acquisition_budget_s));
  EXPECT_DOUBLE_EQ(o.early_termination_window_s, 0.0);
  EXPECT_DOUBLE_EQ(o.time_limit_s, 2.5);  // the outer bound stays
}

TEST(BenchPlannerOptionsTest, DifferentTasksGetDifferentSeeds) {
  const WholeBodyPlannerOptions a = BenchPlannerOptions({}, BenchMethod::kTopay, Settings(2), 1);
  const WholeBodyPlannerOptions b = BenchPlannerOptions({}, BenchMethod::kTopay, Settings(2), 2);
  EXPECT_NE(a.front_end.seed, b.front_end.seed);
}

}  // namespace
}  // namespace topay::bench
