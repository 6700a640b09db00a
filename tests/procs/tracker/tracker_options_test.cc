// topay-tracker's options: the shipped config/tracker/tracker.yaml restates NmpcOptions'
// defaults; a misspelt key or a bad value is a ConfigError naming the field.

#include "procs/tracker/tracker_options.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "tests/common/config_test_file.h"

namespace topay::tracker {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  return topay::test::WriteTestFile("tracker_options", name, text);
}

std::string ErrorOf(const std::string& path) {
  return topay::test::ConfigErrorOf([&] { LoadTrackerOptions(path); });
}

TEST(TrackerOptions, ShippedConfigRestatesTheDefaults) {
  const TrackerOptions o = LoadTrackerOptions(std::string(TOPAY_SOURCE_DIR) + "/config/tracker/tracker.yaml");
  const NmpcOptions d;
  EXPECT_EQ(o.nmpc.horizon_steps, d.horizon_steps);
  EXPECT_DOUBLE_EQ(o.nmpc.step_s, d.step_s);
  EXPECT_DOUBLE_EQ(o.nmpc.control_period_s, d.control_period_s);
  EXPECT_DOUBLE_EQ(o.nmpc.latency_s, d.latency_s);
  EXPECT_DOUBLE_EQ(o.nmpc.time_budget_s, d.time_budget_s);
  EXPECT_EQ(o.nmpc.max_iterations, d.max_iterations);
  EXPECT_DOUBLE_EQ(o.nmpc.position_weight, d.position_weight);
  EXPECT_DOUBLE_EQ(o.nmpc.qdd_weight, d.qdd_weight);
  EXPECT_DOUBLE_EQ(o.nmpc.limit_weight, d.limit_weight);
  EXPECT_DOUBLE_EQ(o.nmpc.stale_state_s, 0.1);
  EXPECT_DOUBLE_EQ(o.nmpc.end_settle_s, d.end_settle_s);
  EXPECT_EQ(o.rebuild.trajectory.integrator.panels_per_piece, 12);
  EXPECT_DOUBLE_EQ(CycleRateHz(o), 50.0);
  const TrackerOptions defaults;
  EXPECT_DOUBLE_EQ(o.jump_position_m, defaults.jump_position_m);
  EXPECT_DOUBLE_EQ(o.jump_yaw_rad, defaults.jump_yaw_rad);
  EXPECT_DOUBLE_EQ(o.lost_position_m, defaults.lost_position_m);
  const PlannerWatchOptions watch;
  EXPECT_EQ(o.planner_watch.process_names, watch.process_names);
  EXPECT_DOUBLE_EQ(o.planner_watch.silence_s, watch.silence_s);
  const ProtectiveFieldOptions field;
  const ProtectiveFieldOptions& f = o.protective_field;
  EXPECT_EQ(f.enabled, field.enabled);
  EXPECT_DOUBLE_EQ(f.reaction_s, field.reaction_s);
  EXPECT_DOUBLE_EQ(f.lookahead_m, field.lookahead_m);
  EXPECT_DOUBLE_EQ(f.radial_margin_m, field.radial_margin_m);
  EXPECT_DOUBLE_EQ(f.z_min_m, field.z_min_m);
  EXPECT_DOUBLE_EQ(f.z_max_m, field.z_max_m);
  EXPECT_EQ(f.min_points, field.min_points);
  EXPECT_DOUBLE_EQ(f.max_scan_age_s, field.max_scan_age_s);
  EXPECT_DOUBLE_EQ(f.step_m, field.step_m);
  EXPECT_DOUBLE_EQ(f.self_margin_m, field.self_margin_m);
}

TEST(TrackerOptions, ReadsValuesAndResolvesRobotPaths) {
  const std::string path = Write("ok.yaml",
                                 "robot_urdf: robot.urdf\nnmpc:\n  horizon_steps: 30\n  stale_state_s: 0.2\n"
                                 "rebuild:\n  panels_per_piece: 8\nrest_command: 0.01\n");
  const TrackerOptions o = LoadTrackerOptions(path);
  EXPECT_EQ(o.nmpc.horizon_steps, 30);
  EXPECT_DOUBLE_EQ(o.nmpc.stale_state_s, 0.2);
  EXPECT_EQ(o.rebuild.trajectory.integrator.panels_per_piece, 8);
  EXPECT_DOUBLE_EQ(o.rest_command, 0.01);
  EXPECT_EQ(o.robot_urdf, (std::filesystem::path(path).parent_path() / "robot.urdf").string());
  EXPECT_TRUE(o.robot_yaml.empty());
}

TEST(TrackerOptions, MisspeltKeyIsAnErrorNamingIt) {
  EXPECT_NE(ErrorOf(Write("typo.yaml", "nmpc:\n  horizon_step: 30\n")).find("nmpc.horizon_step"), std::string::npos);
  EXPECT_NE(ErrorOf(Write("typo_top.yaml", "rate_hz: 50\n")).find("rate_hz"), std::string::npos);
}

TEST(TrackerOptions, BadValuesAreErrorsNamingTheField) {
  EXPECT_NE(ErrorOf(Write("bad.yaml", "nmpc:\n  step_s: -1\n")).find("step_s"), std::string::npos);
  EXPECT_NE(ErrorOf(Write("bad_type.yaml", "nmpc:\n  latency_s: soon\n")).find("nmpc.latency_s"), std::string::npos);
  EXPECT_NE(ErrorOf(Write("bad_panels.yaml", "rebuild:\n  panels_per_piece: 0\n")).find("rebuild.panels_per_piece"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Write("bad_jump.yaml", "jump_yaw_rad: -0.1\n")).find("jump_yaw_rad"), std::string::npos);
  EXPECT_NE(ErrorOf(Write("bad_silence.yaml", "planner_watch:\n  silence_s: -1\n")).find("planner_watch.silence_s"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Write("bad_names.yaml", "planner_watch:\n  process_names: planner\n"))
                .find("planner_watch.process_names"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Write("empty_name.yaml", "planner_watch:\n  process_names: [planner, \"\"]\n"))
                .find("planner_watch.process_names"),
            std::string::npos);
  EXPECT_FALSE(ErrorOf("/nonexistent/tracker.yaml").empty());
}

TEST(TrackerOptions, ReadsTheProtectiveFieldAndNamesItsBadValues) {
  const TrackerOptions o =
      LoadTrackerOptions(Write("field.yaml", "protective_field:\n  enabled: false\n  min_points: 9\n  z_max_m: 0.3\n"));
  EXPECT_FALSE(o.protective_field.enabled);
  EXPECT_EQ(o.protective_field.min_points, 9);
  EXPECT_DOUBLE_EQ(o.protective_field.z_max_m, 0.3);
  const std::string bad = ErrorOf(Write("bad_field.yaml", "protective_field:\n  z_max_m: 0.01\n"));
  EXPECT_NE(bad.find("protective_field"), std::string::npos) << bad;
  EXPECT_NE(bad.find("z_max_m"), std::string::npos) << bad;
  EXPECT_NE(ErrorOf(Write("typo_field.yaml", "protective_field:\n  min_point: 3\n")).find("protective_field.min_point"),
            std::string::npos);
}

TEST(TrackerOptions, ReadsThePlannerWatch) {
  const TrackerOptions o =
      LoadTrackerOptions(Write("watch.yaml", "planner_watch:\n  process_names: [plan-a]\n  silence_s: 0\n"));
  EXPECT_EQ(o.planner_watch.process_names, std::vector<std::string>{"plan-a"});
  EXPECT_EQ(o.planner_watch.silence_s, 0.0);
}

}  // namespace
}  // namespace topay::tracker
