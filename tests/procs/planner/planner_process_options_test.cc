#include "procs/planner/planner_process_options.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace topay::planner {
namespace {

std::string WriteYaml(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / ("topay_planner_" + name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

TEST(PlannerProcessOptionsTest, ShippedFileLoadsWithTheDefaults) {
  const PlannerProcessOptions o = LoadPlannerProcessOptions(TOPAY_SOURCE_DIR "/config/planner/planner.yaml");
  const PlannerProcessOptions d;
  EXPECT_EQ(o.map.unknown, d.map.unknown);
  EXPECT_EQ(o.timing.replan_budget_s, d.timing.replan_budget_s);
  EXPECT_EQ(o.triggers.drift_position_m, d.triggers.drift_position_m);
  EXPECT_EQ(o.triggers.drift_check.position_m, d.triggers.drift_check.position_m);
  EXPECT_EQ(o.triggers.drift_check.yaw_rad, d.triggers.drift_check.yaw_rad);
  EXPECT_EQ(o.triggers.drift_check.joint_rad, d.triggers.drift_check.joint_rad);
  EXPECT_EQ(o.triggers.drift_check.horizon_s, d.triggers.drift_check.horizon_s);
  EXPECT_EQ(o.triggers.drift_check.period_s, d.triggers.drift_check.period_s);
  EXPECT_EQ(o.stop.margin_s, d.stop.margin_s);
  EXPECT_EQ(o.stop.replan_grace_s, d.stop.replan_grace_s);
  EXPECT_EQ(o.map.flush_all_from_rest, d.map.flush_all_from_rest);
  EXPECT_EQ(o.timing.max_failed_plans_from_rest, d.timing.max_failed_plans_from_rest);
  EXPECT_EQ(o.timing.max_state_age_s, d.timing.max_state_age_s);
  EXPECT_EQ(o.goals.reached_position_m, d.goals.reached_position_m);
  EXPECT_EQ(o.map.start_arm_overlap_m, d.map.start_arm_overlap_m);
  EXPECT_EQ(o.map.start_arm_escape_overlap_m, d.map.start_arm_escape_overlap_m);
  EXPECT_EQ(o.goals.reached_orientation_rad, d.goals.reached_orientation_rad);
  EXPECT_EQ(o.triggers.drift_start_tracked, d.triggers.drift_start_tracked);
  EXPECT_TRUE(o.triggers.drift_start_tracked);
  EXPECT_TRUE(std::filesystem::exists(o.planner_config)) << o.planner_config;
  EXPECT_TRUE(std::filesystem::exists(o.tracker_config)) << o.tracker_config;  // beside: ../tracker/tracker.yaml
}

TEST(PlannerProcessOptionsTest, ValuesAreReadAndBadOnesNamed) {
  const PlannerProcessOptions o = LoadPlannerProcessOptions(
      WriteYaml("good", "map: {unknown: occupied, field_update_period_s: 0.5, flush_all_from_rest: false}\n"
                        "timing: {replan_budget_s: 0.4, max_failed_plans_from_rest: 4}\n"
                        "triggers: {drift_check_position_m: 0.07, drift_check_horizon_s: 3.0, drift_start: carried}\n"
                        "tracker_config: my_tracker.yaml\n"
                        "goals: {reached_position_m: 0.01, reached_orientation_rad: 0.02}\nstop: {replan_grace_s: 0.6, grace_reach_m: 3.0}\n"));
  EXPECT_EQ(o.map.unknown, UnknownVoxelPolicy::kOccupied);
  EXPECT_FALSE(o.map.flush_all_from_rest);
  EXPECT_EQ(o.stop.replan_grace_s, 0.6);
  EXPECT_EQ(o.stop.grace_reach_m, 3.0);
  EXPECT_EQ(o.map.field_update_period_s, 0.5);
  EXPECT_EQ(o.timing.replan_budget_s, 0.4);
  EXPECT_EQ(o.timing.max_failed_plans_from_rest, 4);
  EXPECT_EQ(o.triggers.drift_check.position_m, 0.07);
  EXPECT_EQ(o.triggers.drift_check.horizon_s, 3.0);
  EXPECT_FALSE(o.triggers.drift_start_tracked);
  EXPECT_EQ(o.tracker_config, (std::filesystem::temp_directory_path() / "my_tracker.yaml").string());
  EXPECT_EQ(o.goals.reached_position_m, 0.01);
  EXPECT_EQ(o.goals.reached_orientation_rad, 0.02);
  const auto expect_error = [](const std::string& text, const std::string& field) {
    try {
      LoadPlannerProcessOptions(WriteYaml("bad", text));
      ADD_FAILURE() << "accepted: " << text;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  expect_error("map: {unknown: maybe}\n", "map.unknown");
  expect_error("timing: {replan_budget_s: 0.01}\n", "replan_budget_s");
  expect_error("triggers: {drift_position_m: -1}\n", "drift_position_m");
  expect_error("triggers: {drift_check_yaw_rad: 0}\n", "triggers.drift_check_yaw_rad");
  expect_error("triggers: {drift_check_horizon_s: .inf}\n", "triggers.drift_check_horizon_s");
  expect_error("triggers: {drift_check_period_s: -0.1}\n", "triggers.drift_check_period_s");
  expect_error("triggers: {drift_start: extrapolated}\n", "triggers.drift_start");
  expect_error("timing: {max_failed_plans_from_rest: 0}\n", "timing.max_failed_plans_from_rest");
  expect_error("timing: {max_state_age_s: 0}\n", "timing.max_state_age_s");
  expect_error("timing: {max_state_age_s: .nan}\n", "timing.max_state_age_s");
  expect_error("map: {start_arm_overlap_m: -0.01}\n", "map.start_arm_overlap_m");
  expect_error("map: {start_arm_escape_overlap_m: 0.02}\n", "map.start_arm_escape_overlap_m");  // below 0.03
  expect_error("map: {start_arm_escape_overlap_m: .inf}\n", "map.start_arm_escape_overlap_m");
  expect_error("map: {stale_stop_s: -1}\n", "map.stale_stop_s");
  expect_error("goals: {reached_position_m: -0.1}\n", "goals.reached_position_m");
  expect_error("goals: {reached_orientation_rad: .nan}\n", "goals.reached_orientation_rad");
  expect_error("stop: {latency: 1}\n", "stop.latency");
  expect_error("stop: {replan_grace_s: 0}\n", "stop.replan_grace_s");
  expect_error("stop: {grace_reach_m: -1}\n", "stop.grace_reach_m");
  expect_error("status_period_s: .nan\n", "status_period_s");
  expect_error("deterministic: {prm_samples: 0}\n", "deterministic.prm_samples");
  expect_error("deterministic: {rrt_iterations: -3}\n", "deterministic.rrt_iterations");
  expect_error("deterministic: {time_limit_s: 0}\n", "deterministic.time_limit_s");
  expect_error("deterministic: {enable: true}\n", "deterministic.enable");
  expect_error("limits: {acceleration_share: 0}\n", "limits.acceleration_share");
  expect_error("limits: {acceleration_share: 1.2}\n", "limits.acceleration_share");
  expect_error("limits: {acceleration_share: .nan}\n", "limits.acceleration_share");
}

TEST(PlannerProcessOptionsTest, DeterministicModeIsOffByDefaultAndMakesThePlansDependOnWorkBudgets) {
  const PlannerProcessOptions shipped = LoadPlannerProcessOptions(TOPAY_SOURCE_DIR "/config/planner/planner.yaml");
  EXPECT_FALSE(shipped.deterministic.enabled);
  EXPECT_EQ(FieldUpdatePeriod(shipped), shipped.map.field_update_period_s);
  WholeBodyPlannerOptions normal;
  const WholeBodyPlannerOptions defaults;
  AdaptPlannerOptions(shipped, &normal);
  EXPECT_EQ(normal.num_threads, defaults.num_threads);  // untouched on the wall clock
  EXPECT_EQ(normal.time_limit_s, defaults.time_limit_s);

  const PlannerProcessOptions o = LoadPlannerProcessOptions(WriteYaml(
      "deterministic", "deterministic: {enabled: true, prm_samples: 700, rrt_iterations: 90, time_limit_s: 12}\n"));
  EXPECT_TRUE(o.deterministic.enabled);
  EXPECT_EQ(o.deterministic.prm_samples, 700);
  EXPECT_EQ(o.deterministic.rrt_iterations, 90);
  WholeBodyPlannerOptions planner;
  AdaptPlannerOptions(o, &planner);
  EXPECT_EQ(planner.num_threads, 1);
  EXPECT_EQ(planner.front_end.topology.prm.max_samples, 700);
  EXPECT_EQ(planner.front_end.rrt.max_iterations, 90);
  EXPECT_EQ(planner.time_limit_s, 12.0);
  EXPECT_EQ(planner.optimizer.time_limit_s, 12.0) << "a candidate is bounded by the plan's limit, not its own";
  EXPECT_GT(FieldUpdatePeriod(o), 1e5) << "the fields update only when a plan asks";
}

// Finding 16 of docs/reliability.md: plans keep headroom below the limits the bridge enforces.
TEST(PlannerProcessOptionsTest, PlansKeepAShareOfTheAccelerationLimits) {
  const PlannerProcessOptions shipped = LoadPlannerProcessOptions(TOPAY_SOURCE_DIR "/config/planner/planner.yaml");
  EXPECT_LT(shipped.limits.acceleration_share, 1.0);
  RobotModel model;
  model.base_limits = BaseLimits{.v_max_mps = 1.0, .a_max_mps2 = 0.8, .omega_max_radps = 0.9, .beta_max_radps2 = 1.0};
  model.joint_limits.qd_max_radps = Eigen::VectorXd::Constant(7, 1.5);
  model.joint_limits.qdd_max_radps2 = Eigen::VectorXd::Constant(7, 2.0);
  PlannerProcessOptions o;
  o.limits.acceleration_share = 0.5;
  WholeBodyPlannerOptions planner;
  ApplyPlanLimits(o, &model, &planner);
  ASSERT_TRUE(planner.base_limits.has_value());
  EXPECT_DOUBLE_EQ(planner.base_limits->a_max_mps2, 0.4);
  EXPECT_DOUBLE_EQ(planner.base_limits->beta_max_radps2, 0.5);
  EXPECT_DOUBLE_EQ(planner.base_limits->v_max_mps, 1.0) << "speeds untouched";
  EXPECT_DOUBLE_EQ(model.base_limits.a_max_mps2, 0.4);
  EXPECT_DOUBLE_EQ(model.joint_limits.qdd_max_radps2(3), 1.0);
  EXPECT_DOUBLE_EQ(model.joint_limits.qd_max_radps(3), 1.5);
  // Limits the planner config sets (the benchmark's) are scaled the same way.
  WholeBodyPlannerOptions with_limits;
  with_limits.base_limits = BaseLimits{.v_max_mps = 1.0, .a_max_mps2 = 1.0, .omega_max_radps = 1.25, .beta_max_radps2 = 2.0};
  ApplyPlanLimits(o, &model, &with_limits);
  EXPECT_DOUBLE_EQ(with_limits.base_limits->a_max_mps2, 0.5);
  EXPECT_DOUBLE_EQ(with_limits.base_limits->beta_max_radps2, 1.0);
}

}  // namespace
}  // namespace topay::planner
