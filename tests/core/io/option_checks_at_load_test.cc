// Values are checked where they are read: every range rule of the options the planner YAML
// sets fails at load, as a ConfigError naming the YAML field, not later when the planner is
// built or run (a tool's exit code 1, not 3).
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/planner_config.h"
#include "tests/core/io/planner_config_cases.h"

namespace topay {
namespace {

TEST(OptionChecksAtLoadTest, PlannerAndBaseLimits) {
  const testing::BadConfigCase cases[] = {
      {"planner: {time_limit_s: -1}", "planner.time_limit_s"},
      {"planner: {time_limit_s: 0}", "planner.time_limit_s"},
      {"planner: {time_limit_s: -.inf}", "planner.time_limit_s"},
      {"planner: {early_termination_window_s: -0.1}", "planner.early_termination_window_s"},
      {"planner: {num_threads: -1}", "planner.num_threads"},
      {"planner: {max_candidates: 0}", "planner.max_candidates"},
      {"planner: {base_limits: {v_max_mps: -1}}", "planner.base_limits.v_max_mps"},
      {"planner: {base_limits: {v_max_mps: 1, omega_max_radps: 0}}",
       "planner.base_limits.omega_max_radps"},
      {"planner: {base_limits: {beta_max_radps2: .inf}}", "planner.base_limits.beta_max_radps2"},
  };
  for (const testing::BadConfigCase& c : cases) testing::ExpectConfigErrorNamesTheField(c);
}

TEST(OptionChecksAtLoadTest, FrontEnd) {
  const testing::BadConfigCase cases[] = {
      {"front_end: {max_goal_attempts: 0}", "front_end.max_goal_attempts"},
      {"front_end: {fallback_base_clearance_m: -0.1}", "front_end.fallback_base_clearance_m"},
      {"front_end: {other_way_turn_min_rad: -1}", "front_end.other_way_turn_min_rad"},
      {"front_end: {other_way_turn_min_rad: .nan}", "front_end.other_way_turn_min_rad"},
      {"front_end: {improvement_window_s: -1}", "front_end.improvement_window_s"},
      {"front_end: {acquisition_budget_s: -1}", "front_end.acquisition_budget_s"},
      {"front_end: {acquisition_budget_s: 0}", "front_end.acquisition_budget_s"},
      {"front_end: {num_threads: -2}", "front_end.num_threads"},
      {"front_end: {goal: {max_candidates: 0}}", "front_end.goal.max_candidates"},
      {"front_end: {goal: {travel_weight: 1, clearance_weight: -1}}",
       "front_end.goal.clearance_weight"},
      {"front_end: {ik: {max_solutions: 0}}", "front_end.ik.max_solutions"},
      {"front_end: {ik: {time_budget_s: -1}}", "front_end.ik.time_budget_s"},
      {"front_end: {ik: {position_tolerance_m: 0}}", "front_end.ik.position_tolerance_m"},
      {"front_end: {ik: {restarts_per_base: 0}}", "front_end.ik.restarts_per_base"},
      {"front_end: {ik: {max_base_candidates: -1}}", "front_end.ik.max_base_candidates"},
      {"front_end: {topology: {clearance_m: -1}}", "front_end.topology.clearance_m"},
      {"front_end: {topology: {prm: {sample_half_width_m: -1}}}",
       "front_end.topology.prm.sample_half_width_m"},
      {"front_end: {topology: {prm: {max_samples: 10, sample_margin_length_m: .inf}}}",
       "front_end.topology.prm.sample_margin_length_m"},
      {"front_end: {topology: {pruning: {max_length_ratio: 0.5}}}",
       "front_end.topology.pruning.max_length_ratio"},
      {"front_end: {discretisation: {delta_l_m: 0}}", "front_end.discretisation.delta_l_m"},
      {"front_end: {discretisation: {max_turn_step_rad: -1}}",
       "front_end.discretisation.max_turn_step_rad"},
      {"front_end: {rrt: {time_budget_s: -1}}", "front_end.rrt.time_budget_s"},
      {"front_end: {rrt: {goal_bias: 2}}", "front_end.rrt.goal_bias"},
      {"front_end: {rrt: {goal_bias: 0.5, stow_bias: -0.1}}", "front_end.rrt.stow_bias"},
      {"front_end: {rrt: {rewire_radius_rad: -1}}", "front_end.rrt.rewire_radius_rad"},
      {"front_end: {rrt: {max_neighbours: 0}}", "front_end.rrt.max_neighbours"},
      {"front_end: {rrt: {max_informed_draws: -1}}", "front_end.rrt.max_informed_draws"},
      {"front_end: {rrt: {max_nodes: 1}}", "front_end.rrt.max_nodes"},
      {"front_end: {validity: {self_margin_m: .inf}}", "front_end.validity.self_margin_m"},
      {"front_end: {validity: {max_edge_step_m: 0}}", "front_end.validity.max_edge_step_m"},
      {"front_end: {validity: {max_edge_step_m: 0.1, max_edge_step_rad: -1}}",
       "front_end.validity.max_edge_step_rad"},
  };
  for (const testing::BadConfigCase& c : cases) testing::ExpectConfigErrorNamesTheField(c);
}

TEST(OptionChecksAtLoadTest, Optimizer) {
  const testing::BadConfigCase cases[] = {
      {"optimizer: {time_limit_s: -1}", "optimizer.time_limit_s"},
      {"optimizer: {stage1_max_iterations: -1}", "optimizer.stage1_max_iterations"},
      {"optimizer: {max_penalty_escalations: -1}", "optimizer.max_penalty_escalations"},
      {"optimizer: {penalty_escalation_factor: 0.5}", "optimizer.penalty_escalation_factor"},
      {"optimizer: {clearance_escalation_step_m: -1}", "optimizer.clearance_escalation_step_m"},
      {"optimizer: {joint_escalation_step_rad: -1}", "optimizer.joint_escalation_step_rad"},
      {"optimizer: {rate_escalation_step: 1}", "optimizer.rate_escalation_step"},
      {"optimizer: {ee_position_tolerance_m: 0.02, ee_orientation_tolerance_rad: 0}",
       "optimizer.ee_orientation_tolerance_rad"},
      {"optimizer: {alm: {rho_initial: 0}}", "optimizer.alm.rho_initial"},
      {"optimizer: {alm: {rho_growth: 0.5}}", "optimizer.alm.rho_growth"},
      {"optimizer: {alm: {rho_max: 1}}", "optimizer.alm.rho_max"},
      {"optimizer: {alm: {max_outer_iterations: 0}}", "optimizer.alm.max_outer_iterations"},
      {"optimizer: {alm: {position_tolerance_m: 0.01, orientation_tolerance_rad: -1}}",
       "optimizer.alm.orientation_tolerance_rad"},
      {"optimizer: {warm_start: {piece_duration_s: 0}}", "optimizer.warm_start.piece_duration_s"},
      {"optimizer: {warm_start: {piece_duration_s: 2, min_pieces: 0}}",
       "optimizer.warm_start.min_pieces"},
      {"optimizer: {warm_start: {max_pieces: 2}}", "optimizer.warm_start.max_pieces"},
      {"optimizer: {warm_start: {rate_fraction: 1.5}}", "optimizer.warm_start.rate_fraction"},
      {"optimizer: {warm_start: {min_duration_s: -1}}", "optimizer.warm_start.min_duration_s"},
      {"optimizer: {lbfgs: {memory: 0}}", "optimizer.lbfgs.memory"},
      {"optimizer: {lbfgs: {memory: 32, curvature: 1.5}}", "optimizer.lbfgs.curvature"},
      {"optimizer: {lbfgs: {max_iterations: 0}}", "optimizer.lbfgs.max_iterations"},
      {"optimizer: {lbfgs: {relative_decrease_delta: -1}}",
       "optimizer.lbfgs.relative_decrease_delta"},
      {"optimizer: {lbfgs: {sufficient_decrease: 0}}", "optimizer.lbfgs.sufficient_decrease"},
      {"optimizer: {objective: {time_weight: -1}}", "optimizer.objective.time_weight"},
      {"optimizer: {objective: {panels_per_piece: 0}}", "optimizer.objective.panels_per_piece"},
      {"optimizer: {objective: {path_fit_angle_weight: -1}}",
       "optimizer.objective.path_fit_angle_weight"},
      {"optimizer: {objective: {jerk_weights: {arc_length: 1, yaw: -1}}}",
       "optimizer.objective.jerk_weights.yaw"},
      {"optimizer: {objective: {jerk_weights: {joint: -1}}}",
       "optimizer.objective.jerk_weights.joint"},
      {"optimizer: {feasibility: {sample_period_s: 0}}", "optimizer.feasibility.sample_period_s"},
      {"optimizer: {feasibility: {rate_tolerance: -1}}", "optimizer.feasibility.rate_tolerance"},
  };
  for (const testing::BadConfigCase& c : cases) testing::ExpectConfigErrorNamesTheField(c);
}

// The penalty options were checked only when the optimizer was built (std::invalid_argument
// from the planner's constructor: a failed plan, not a config error).
TEST(OptionChecksAtLoadTest, Penalties) {
  const std::string prefix = "optimizer.objective.penalties.";
  for (const char* key :
       {"velocity_omega_weight", "acceleration_weight", "yaw_acceleration_weight",
        "joint_position_weight", "joint_velocity_weight", "joint_acceleration_weight",
        "base_obstacle_weight", "arm_obstacle_weight", "self_collision_weight",
        "chassis_weight", "joint_position_margin_rad"}) {
    const std::string yaml = std::string("optimizer: {objective: {penalties: {smoothing_mu: 0.5, ") +
                             key + ": -1}}}";
    testing::ExpectConfigErrorNamesTheField({yaml.c_str(), (prefix + key).c_str()});
  }
  const testing::BadConfigCase cases[] = {
      {"optimizer: {objective: {penalties: {smoothing_mu: 0}}}",
       "optimizer.objective.penalties.smoothing_mu"},
      {"optimizer: {objective: {penalties: {base_radius_factor: 0}}}",
       "optimizer.objective.penalties.base_radius_factor"},
      {"optimizer: {objective: {penalties: {sphere_radius_factor: -1}}}",
       "optimizer.objective.penalties.sphere_radius_factor"},
      {"optimizer: {objective: {penalties: {rate_limit_fraction: 1.5}}}",
       "optimizer.objective.penalties.rate_limit_fraction"},
      {"optimizer: {objective: {penalties: {self_margin_m: .inf}}}",
       "optimizer.objective.penalties.self_margin_m"},
      {"optimizer: {objective: {penalties: {chassis_margin_m: -.inf}}}",
       "optimizer.objective.penalties.chassis_margin_m"},
  };
  for (const testing::BadConfigCase& c : cases) testing::ExpectConfigErrorNamesTheField(c);
}

TEST(OptionChecksAtLoadTest, Validator) {
  const testing::BadConfigCase cases[] = {
      {"validator: {sample_period_s: 0}", "validator.sample_period_s"},
      {"validator: {sample_period_s: 0.01, limit_tolerance: -1}", "validator.limit_tolerance"},
      {"validator: {ee_position_tolerance_m: -1}", "validator.ee_position_tolerance_m"},
      {"validator: {ee_orientation_tolerance_rad: .inf}", "validator.ee_orientation_tolerance_rad"},
      {"validator: {obstacle_margin_m: -0.01}", "validator.obstacle_margin_m"},
      {"validator: {self_margin_m: -0.01}", "validator.self_margin_m"},
  };
  for (const testing::BadConfigCase& c : cases) testing::ExpectConfigErrorNamesTheField(c);
}

// The message says what is wrong, not only where.
TEST(OptionChecksAtLoadTest, TheMessageStatesTheRule) {
  try {
    ParsePlannerOptions("optimizer: {objective: {penalties: {chassis_weight: -3}}}", "x.yaml");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("x.yaml: optimizer.objective.penalties.chassis_weight: "),
              std::string::npos)
        << what;
    EXPECT_NE(what.find(">= 0"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace topay
