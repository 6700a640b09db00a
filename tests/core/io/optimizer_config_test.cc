#include "core/io/optimizer_config.h"

#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "tests/core/io/planner_config_cases.h"
#include "core/io/planner_config.h"

namespace topay {
namespace {

const std::string kShipped = TOPAY_SOURCE_DIR "/config/planner/topay.yaml";

// The shipped file's optimizer section restates every default.
TEST(OptimizerConfigTest, ShippedFileRestatesTheDefaults) {
  const TrajectoryOptimizerOptions o = LoadPlannerOptions(kShipped).optimizer;
  const TrajectoryOptimizerOptions d;
  EXPECT_EQ(o.time_limit_s, d.time_limit_s);
  EXPECT_EQ(o.run_stage1, d.run_stage1);
  EXPECT_EQ(o.stage1_max_iterations, d.stage1_max_iterations);
  EXPECT_EQ(o.max_penalty_escalations, d.max_penalty_escalations);
  EXPECT_EQ(o.penalty_escalation_factor, d.penalty_escalation_factor);
  EXPECT_EQ(o.clearance_escalation_step_m, d.clearance_escalation_step_m);
  EXPECT_EQ(o.joint_escalation_step_rad, d.joint_escalation_step_rad);
  EXPECT_EQ(o.rate_escalation_step, d.rate_escalation_step);
  EXPECT_EQ(o.ee_position_tolerance_m, d.ee_position_tolerance_m);
  EXPECT_EQ(o.ee_orientation_tolerance_rad, d.ee_orientation_tolerance_rad);
  EXPECT_EQ(o.alm.rho_initial, d.alm.rho_initial);
  EXPECT_EQ(o.alm.rho_growth, d.alm.rho_growth);
  EXPECT_EQ(o.alm.rho_max, d.alm.rho_max);
  EXPECT_EQ(o.alm.max_outer_iterations, d.alm.max_outer_iterations);
  EXPECT_EQ(o.alm.position_tolerance_m, d.alm.position_tolerance_m);
  EXPECT_EQ(o.alm.orientation_tolerance_rad, d.alm.orientation_tolerance_rad);
  EXPECT_EQ(o.warm_start.piece_duration_s, d.warm_start.piece_duration_s);
  EXPECT_EQ(o.warm_start.min_pieces, d.warm_start.min_pieces);
  EXPECT_EQ(o.warm_start.max_pieces, d.warm_start.max_pieces);
  EXPECT_EQ(o.warm_start.rate_fraction, d.warm_start.rate_fraction);
  EXPECT_EQ(o.warm_start.min_duration_s, d.warm_start.min_duration_s);
  EXPECT_EQ(o.lbfgs.memory, d.lbfgs.memory);
  EXPECT_EQ(o.lbfgs.max_iterations, d.lbfgs.max_iterations);
  EXPECT_EQ(o.lbfgs.relative_decrease_delta, d.lbfgs.relative_decrease_delta);
  EXPECT_EQ(o.lbfgs.relative_decrease_past, d.lbfgs.relative_decrease_past);
  EXPECT_EQ(o.lbfgs.sufficient_decrease, d.lbfgs.sufficient_decrease);
  EXPECT_EQ(o.lbfgs.curvature, d.lbfgs.curvature);
  const TrajectoryObjectiveOptions& a = o.objective;
  const TrajectoryObjectiveOptions& b = d.objective;
  EXPECT_EQ(a.time_weight, b.time_weight);
  EXPECT_EQ(a.panels_per_piece, b.panels_per_piece);
  EXPECT_EQ(a.sample_chunks, b.sample_chunks);
  EXPECT_EQ(a.path_fit_position_weight, b.path_fit_position_weight);
  EXPECT_EQ(a.path_fit_angle_weight, b.path_fit_angle_weight);
  EXPECT_EQ(a.jerk_weights.arc_length, b.jerk_weights.arc_length);
  EXPECT_EQ(a.jerk_weights.yaw, b.jerk_weights.yaw);
  EXPECT_EQ(a.jerk_weights.joint, b.jerk_weights.joint);
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    const auto term = static_cast<PenaltyTerm>(t);
    EXPECT_EQ(a.penalties.Weight(term), b.penalties.Weight(term)) << ToString(term);
  }
  EXPECT_EQ(a.penalties.smoothing_mu, b.penalties.smoothing_mu);
  EXPECT_EQ(a.penalties.base_radius_factor, b.penalties.base_radius_factor);
  EXPECT_EQ(a.penalties.sphere_radius_factor, b.penalties.sphere_radius_factor);
  EXPECT_EQ(a.penalties.rate_limit_fraction, b.penalties.rate_limit_fraction);
  EXPECT_EQ(a.penalties.joint_position_margin_rad, b.penalties.joint_position_margin_rad);
  EXPECT_EQ(a.penalties.self_margin_m, b.penalties.self_margin_m);
  EXPECT_EQ(a.penalties.chassis_margin_m, b.penalties.chassis_margin_m);
  EXPECT_EQ(o.feasibility.sample_period_s, d.feasibility.sample_period_s);
  EXPECT_EQ(o.feasibility.rate_tolerance, d.feasibility.rate_tolerance);
}

TEST(OptimizerConfigTest, FieldsOverrideDefaults) {
  const TrajectoryOptimizerOptions o = ParsePlannerOptions(R"(
optimizer:
  time_limit_s: 1.5
  alm: {rho_initial: 100.0, max_outer_iterations: 4}
  warm_start: {piece_duration_s: 2.5}
  lbfgs: {memory: 32}
  objective:
    sample_chunks: 3
    jerk_weights: {yaw: 0.5}
    penalties: {arm_obstacle_weight: 1.0e+6, self_margin_m: 0.02}
  feasibility: {rate_tolerance: 0.005}
)", "inline").optimizer;
  EXPECT_EQ(o.time_limit_s, 1.5);
  EXPECT_EQ(o.alm.rho_initial, 100.0);
  EXPECT_EQ(o.alm.max_outer_iterations, 4);
  EXPECT_EQ(o.warm_start.piece_duration_s, 2.5);
  EXPECT_EQ(o.lbfgs.memory, 32);
  EXPECT_EQ(o.objective.sample_chunks, 3);
  EXPECT_EQ(o.objective.jerk_weights.yaw, 0.5);
  EXPECT_EQ(o.objective.penalties.arm_obstacle_weight, 1.0e6);
  EXPECT_EQ(o.objective.penalties.self_margin_m, 0.02);
  EXPECT_EQ(o.feasibility.rate_tolerance, 0.005);
  // Untouched fields keep their defaults.
  const TrajectoryOptimizerOptions d;
  EXPECT_EQ(o.alm.rho_growth, d.alm.rho_growth);
  EXPECT_EQ(o.objective.jerk_weights.arc_length, d.objective.jerk_weights.arc_length);
  EXPECT_EQ(o.objective.penalties.base_obstacle_weight, d.objective.penalties.base_obstacle_weight);
}

TEST(OptimizerConfigTest, BadValuesNameTheField) {
  const testing::BadConfigCase cases[] = {
      {"optimizer: {alm: {rho_initial: big}}", "optimizer.alm.rho_initial"},
      {"optimizer: {lbfgs: {memory: 2.5}}", "optimizer.lbfgs.memory"},
      {"optimizer: {objective: {penalties: {arm_weight: 1}}}",
       "optimizer.objective.penalties.arm_weight"},
      {"optimizer: {warm_start: {pieces: 3}}", "optimizer.warm_start.pieces"},
      {"optimizer: {run_stage1: sometimes}", "optimizer.run_stage1"},
  };
  for (const testing::BadConfigCase& c : cases) testing::ExpectConfigErrorNamesTheField(c);
}

TEST(OptimizerConfigTest, OutOfRangeValuesAreConfigErrors) {
  for (const char* yaml : {"optimizer: {objective: {sample_chunks: 0}}",
                           "optimizer: {warm_start: {piece_duration_s: 0}}",
                           "optimizer: {alm: {rho_growth: 0.5}}",
                           "optimizer: {lbfgs: {curvature: 1.5}}",
                           "optimizer: {feasibility: {sample_period_s: -1}}"}) {
    EXPECT_THROW(ParsePlannerOptions(yaml, "x.yaml"), ConfigError) << yaml;
  }
}

}  // namespace
}  // namespace topay
