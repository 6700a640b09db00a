#include "tools/topay_bench/bench_method.h"

#include <gtest/gtest.h>

namespace topay::bench {
namespace {

TEST(BenchMethodTest, NamesRoundTrip) {
  for (BenchMethod method : AllBenchMethods()) {
    EXPECT_EQ(ParseBenchMethod(BenchMethodName(method)), method) << BenchMethodName(method);
  }
  EXPECT_EQ(BenchMethodName(BenchMethod::kJpsOnly), "jps-only");
  EXPECT_FALSE(ParseBenchMethod("TopAY").has_value());
  EXPECT_FALSE(ParseBenchMethod("").has_value());
}

// Options with every field the methods touch set away from what the methods set.
WholeBodyPlannerOptions Loaded() {
  WholeBodyPlannerOptions options;
  options.front_end.topology.mode = BasePathMode::kTopologicalWithJps;
  options.sequential = false;
  options.max_candidates = 5;
  options.optimizer.parameterisation = TrajectoryParameterisation::kArcLengthYaw;
  options.time_limit_s = 7.0;
  return options;
}

TEST(BenchMethodTest, TopayKeepsTheLoadedOptions) {
  WholeBodyPlannerOptions options = Loaded();
  ApplyBenchMethod(BenchMethod::kTopay, &options);
  EXPECT_EQ(options.front_end.topology.mode, BasePathMode::kTopologicalWithJps);
  EXPECT_FALSE(options.sequential);
  EXPECT_EQ(options.max_candidates, 5);
  EXPECT_EQ(options.optimizer.parameterisation, TrajectoryParameterisation::kArcLengthYaw);
}

TEST(BenchMethodTest, JpsOnlyChangesOnlyTheBasePathMode) {
  WholeBodyPlannerOptions options = Loaded();
  ApplyBenchMethod(BenchMethod::kJpsOnly, &options);
  EXPECT_EQ(options.front_end.topology.mode, BasePathMode::kJpsOnly);
  EXPECT_FALSE(options.sequential);
  EXPECT_EQ(options.max_candidates, 5);
  EXPECT_EQ(options.optimizer.parameterisation, TrajectoryParameterisation::kArcLengthYaw);
}

TEST(BenchMethodTest, SequentialSetsTheAblationFlag) {
  WholeBodyPlannerOptions options = Loaded();
  ApplyBenchMethod(BenchMethod::kSequential, &options);
  EXPECT_TRUE(options.sequential);
  EXPECT_EQ(options.front_end.topology.mode, BasePathMode::kTopologicalWithJps);
  EXPECT_EQ(options.max_candidates, 5);
}

TEST(BenchMethodTest, FlatnessIsTheGreedySinglePathBaseline) {
  WholeBodyPlannerOptions options = Loaded();
  ApplyBenchMethod(BenchMethod::kFlatness, &options);
  EXPECT_EQ(options.optimizer.parameterisation, TrajectoryParameterisation::kFlatness);
  EXPECT_EQ(options.front_end.topology.mode, BasePathMode::kJpsOnly);
  EXPECT_EQ(options.max_candidates, 1);
  EXPECT_FALSE(options.sequential);
  EXPECT_EQ(options.time_limit_s, 7.0);
}

}  // namespace
}  // namespace topay::bench
