#include "core/io/planner_config.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "tests/core/io/planner_config_cases.h"

namespace topay {
namespace {

const std::string kShipped = TOPAY_SOURCE_DIR "/config/planner/topay.yaml";

// The shipped file restates the defaults: loading it gives the struct defaults, field by field
// for every field it names.
TEST(PlannerConfigTest, ShippedFileLoadsAndRestatesTheDefaults) {
  const WholeBodyPlannerOptions loaded = LoadPlannerOptions(kShipped);
  const WholeBodyPlannerOptions d;
  EXPECT_EQ(loaded.early_termination_window_s, d.early_termination_window_s);
  EXPECT_EQ(loaded.sequential, d.sequential);
  EXPECT_EQ(loaded.time_limit_s, d.time_limit_s);
  EXPECT_EQ(loaded.max_candidates, d.max_candidates);
  EXPECT_EQ(loaded.retry.max_rounds, d.retry.max_rounds);
  EXPECT_EQ(loaded.retry.min_time_left_s, d.retry.min_time_left_s);
  EXPECT_EQ(loaded.retry.clearance_step_m, d.retry.clearance_step_m);
  EXPECT_FALSE(loaded.base_limits.has_value());
  const FrontEndOptions& f = loaded.front_end;
  EXPECT_EQ(f.max_goal_attempts, d.front_end.max_goal_attempts);
  EXPECT_EQ(f.fallback_base_clearance_m, d.front_end.fallback_base_clearance_m);
  EXPECT_EQ(f.reachable_goal_search, d.front_end.reachable_goal_search);
  EXPECT_EQ(f.other_way_turn_min_rad, d.front_end.other_way_turn_min_rad);
  EXPECT_EQ(f.improvement_window_s, d.front_end.improvement_window_s);
  EXPECT_EQ(f.acquisition_budget_s, d.front_end.acquisition_budget_s);
  EXPECT_EQ(f.seed, d.front_end.seed);
  EXPECT_EQ(f.goal.max_candidates, d.front_end.goal.max_candidates);
  EXPECT_EQ(f.goal.clearance_weight, d.front_end.goal.clearance_weight);
  EXPECT_EQ(f.ik.max_solutions, d.front_end.ik.max_solutions);
  EXPECT_EQ(f.ik.time_budget_s, d.front_end.ik.time_budget_s);
  EXPECT_EQ(f.ik.position_tolerance_m, d.front_end.ik.position_tolerance_m);
  EXPECT_EQ(f.topology.mode, d.front_end.topology.mode);
  EXPECT_EQ(f.topology.clearance_m, d.front_end.topology.clearance_m);
  EXPECT_EQ(f.topology.prm.max_samples, d.front_end.topology.prm.max_samples);
  EXPECT_EQ(f.topology.prm.max_time_s, d.front_end.topology.prm.max_time_s);
  EXPECT_EQ(f.topology.prm.sample_half_width_m, d.front_end.topology.prm.sample_half_width_m);
  EXPECT_EQ(f.topology.enumeration.max_raw_paths, d.front_end.topology.enumeration.max_raw_paths);
  EXPECT_EQ(f.topology.enumeration.keep_fewest_hops,
            d.front_end.topology.enumeration.keep_fewest_hops);
  EXPECT_EQ(f.topology.pruning.max_paths, d.front_end.topology.pruning.max_paths);
  EXPECT_EQ(f.topology.pruning.resolution_m, d.front_end.topology.pruning.resolution_m);
  EXPECT_EQ(f.topology.shortcut.resample_step_m, d.front_end.topology.shortcut.resample_step_m);
  EXPECT_EQ(f.topology.pruning.max_length_ratio, d.front_end.topology.pruning.max_length_ratio);
  EXPECT_EQ(f.discretisation.delta_l_m, d.front_end.discretisation.delta_l_m);
  EXPECT_DOUBLE_EQ(f.discretisation.max_turn_step_rad, d.front_end.discretisation.max_turn_step_rad);
  EXPECT_EQ(f.rrt.time_budget_s, d.front_end.rrt.time_budget_s);
  EXPECT_EQ(f.rrt.stop_at_first_solution, d.front_end.rrt.stop_at_first_solution);
  EXPECT_EQ(f.rrt.goal_bias, d.front_end.rrt.goal_bias);
  EXPECT_EQ(f.rrt.max_nodes, d.front_end.rrt.max_nodes);
  EXPECT_EQ(f.validity.max_edge_step_m, d.front_end.validity.max_edge_step_m);
  EXPECT_EQ(loaded.validator.sample_period_s, d.validator.sample_period_s);
  EXPECT_EQ(loaded.validator.limit_tolerance, d.validator.limit_tolerance);
  EXPECT_EQ(loaded.validator.ee_position_tolerance_m, d.validator.ee_position_tolerance_m);
}

TEST(PlannerConfigTest, FieldsOverrideDefaults) {
  const WholeBodyPlannerOptions o = ParsePlannerOptions(R"(
planner:
  sequential: true
  time_limit_s: .inf
  retry: {max_rounds: 1, min_time_left_s: 0.5}
  base_limits: {omega_max_radps: 1.25}
front_end:
  seed: 42
  topology: {mode: jps_only, prm: {max_samples: 100}}
  rrt: {goal_bias: 0.25}
validator: {sample_period_s: 0.005}
)", "inline");
  EXPECT_TRUE(o.sequential);
  EXPECT_TRUE(std::isinf(o.time_limit_s));
  EXPECT_EQ(o.retry.max_rounds, 1);
  EXPECT_EQ(o.retry.min_time_left_s, 0.5);
  EXPECT_EQ(o.retry.clearance_step_m, PlanRetryOptions{}.clearance_step_m);
  EXPECT_EQ(o.retry.arm_budget_growth, PlanRetryOptions{}.arm_budget_growth);
  ASSERT_TRUE(o.base_limits.has_value());
  EXPECT_EQ(o.base_limits->omega_max_radps, 1.25);
  EXPECT_EQ(o.base_limits->v_max_mps, BaseLimits{}.v_max_mps);
  EXPECT_EQ(o.front_end.seed, 42u);
  EXPECT_EQ(o.front_end.topology.mode, BasePathMode::kJpsOnly);
  EXPECT_EQ(o.front_end.topology.prm.max_samples, 100);
  EXPECT_EQ(o.front_end.rrt.goal_bias, 0.25);
  EXPECT_EQ(o.validator.sample_period_s, 0.005);
  // Untouched fields keep their defaults.
  EXPECT_EQ(o.max_candidates, WholeBodyPlannerOptions{}.max_candidates);
}

// Each bad file names the file and the dotted field.
TEST(PlannerConfigTest, BadValuesNameTheField) {
  const testing::BadConfigCase cases[] = {
      {"front_end: {rrt: {goal_bias: high}}", "front_end.rrt.goal_bias"},
      {"front_end: {rrt: {goal_bais: 0.3}}", "front_end.rrt.goal_bais"},
      {"front_end: {topology: {prm: {max_samples: 2.5}}}", "front_end.topology.prm.max_samples"},
      {"front_end: {topology: {mode: fastest}}", "front_end.topology.mode"},
      {"front_end: {seed: -3}", "front_end.seed"},
      {"planner: {sequential: maybe}", "planner.sequential"},
      {"planner: {time_limit_s: .nan}", "planner.time_limit_s"},
      {"planner: {time_limit_s: [1, 2]}", "planner.time_limit_s"},
      {"planner: {base_limits: {omega: 1}}", "planner.base_limits.omega"},
      {"planner: {retry: {rounds: 2}}", "planner.retry.rounds"},
      {"planner: {retry: {max_rounds: 0}}", "planner.retry.max_rounds"},
      {"planner: {retry: {clearance_step_m: -0.1}}", "planner.retry.clearance_step_m"},
      {"planner: {retry: {arm_budget_growth: 0.5}}", "planner.retry.arm_budget_growth"},
      {"planner: {retry: {warm_start_slowdown: 0}}", "planner.retry.warm_start_slowdown"},
      {"planner: {retry: {warm_start_slowdown: 1.5}}", "planner.retry.warm_start_slowdown"},
      {"plnner: {}", "plnner"},
      {"front_end: 3", "front_end"},
  };
  for (const testing::BadConfigCase& c : cases) testing::ExpectConfigErrorNamesTheField(c);
}

TEST(PlannerConfigTest, RangeChecksAndFileErrorsAreConfigErrors) {
  EXPECT_THROW(ParsePlannerOptions("planner: {max_candidates: 0}", "x.yaml"), ConfigError);
  EXPECT_THROW(ParsePlannerOptions("front_end: {max_goal_attempts: 0}", "x.yaml"), ConfigError);
  EXPECT_THROW(ParsePlannerOptions("planner: {max_candidates: [", "x.yaml"), ConfigError);
  // The issue's `--config /tmp`: a directory is not an empty configuration.
  try {
    LoadPlannerOptions(::testing::TempDir());
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), ::testing::TempDir());
    EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos) << e.what();
  }
  try {
    LoadPlannerOptions("/nonexistent/planner.yaml");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/planner.yaml");
  }
}

}  // namespace
}  // namespace topay
