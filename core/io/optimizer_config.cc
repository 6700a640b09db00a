#include "core/io/optimizer_config.h"

namespace topay {
namespace {

void ReadAlm(YamlSection section, AugmentedLagrangianOptions* o) {
  section.Read("rho_initial", &o->rho_initial);
  section.Read("rho_growth", &o->rho_growth);
  section.Read("rho_max", &o->rho_max);
  section.Read("max_outer_iterations", &o->max_outer_iterations);
  section.Read("position_tolerance_m", &o->position_tolerance_m);
  section.Read("orientation_tolerance_rad", &o->orientation_tolerance_rad);
  section.Finish();
}

void ReadWarmStart(YamlSection section, WarmStartOptions* o) {
  section.Read("piece_duration_s", &o->piece_duration_s);
  section.Read("min_pieces", &o->min_pieces);
  section.Read("max_pieces", &o->max_pieces);
  section.Read("rate_fraction", &o->rate_fraction);
  section.Read("min_duration_s", &o->min_duration_s);
  section.Finish();
}

void ReadLbfgs(YamlSection section, LbfgsOptions* o) {
  section.Read("memory", &o->memory);
  section.Read("max_iterations", &o->max_iterations);
  section.Read("relative_decrease_delta", &o->relative_decrease_delta);
  section.Read("relative_decrease_past", &o->relative_decrease_past);
  section.Read("sufficient_decrease", &o->sufficient_decrease);
  section.Read("curvature", &o->curvature);
  section.Finish();
}

void ReadPenalties(YamlSection section, SamplePenaltyOptions* o) {
  section.Read("smoothing_mu", &o->smoothing_mu);
  section.Read("velocity_omega_weight", &o->velocity_omega_weight);
  section.Read("acceleration_weight", &o->acceleration_weight);
  section.Read("yaw_acceleration_weight", &o->yaw_acceleration_weight);
  section.Read("joint_position_weight", &o->joint_position_weight);
  section.Read("joint_velocity_weight", &o->joint_velocity_weight);
  section.Read("joint_acceleration_weight", &o->joint_acceleration_weight);
  section.Read("base_obstacle_weight", &o->base_obstacle_weight);
  section.Read("arm_obstacle_weight", &o->arm_obstacle_weight);
  section.Read("self_collision_weight", &o->self_collision_weight);
  section.Read("chassis_weight", &o->chassis_weight);
  section.Read("base_radius_factor", &o->base_radius_factor);
  section.Read("sphere_radius_factor", &o->sphere_radius_factor);
  section.Read("rate_limit_fraction", &o->rate_limit_fraction);
  section.Read("joint_position_margin_rad", &o->joint_position_margin_rad);
  section.Read("self_margin_m", &o->self_margin_m);
  section.Read("chassis_margin_m", &o->chassis_margin_m);
  section.Finish();
}

void ReadObjective(YamlSection section, TrajectoryObjectiveOptions* o) {
  YamlSection jerk = section.Section("jerk_weights");
  jerk.Read("arc_length", &o->jerk_weights.arc_length);
  jerk.Read("yaw", &o->jerk_weights.yaw);
  jerk.Read("joint", &o->jerk_weights.joint);
  jerk.Finish();
  section.Read("time_weight", &o->time_weight);
  section.Read("panels_per_piece", &o->panels_per_piece);
  section.Read("sample_chunks", &o->sample_chunks);
  section.Read("path_fit_position_weight", &o->path_fit_position_weight);
  section.Read("path_fit_angle_weight", &o->path_fit_angle_weight);
  ReadPenalties(section.Section("penalties"), &o->penalties);
  section.Finish();
}

void ReadFeasibility(YamlSection section, FieldFeasibilityOptions* o) {
  section.Read("sample_period_s", &o->sample_period_s);
  section.Read("rate_tolerance", &o->rate_tolerance);
  section.Finish();
}

}  // namespace

void ReadOptimizerOptions(YamlSection section, TrajectoryOptimizerOptions* o) {
  section.Read("time_limit_s", &o->time_limit_s);
  section.Read("run_stage1", &o->run_stage1);
  section.Read("stage1_max_iterations", &o->stage1_max_iterations);
  section.Read("max_penalty_escalations", &o->max_penalty_escalations);
  section.Read("penalty_escalation_factor", &o->penalty_escalation_factor);
  section.Read("clearance_escalation_step_m", &o->clearance_escalation_step_m);
  section.Read("joint_escalation_step_rad", &o->joint_escalation_step_rad);
  section.Read("rate_escalation_step", &o->rate_escalation_step);
  section.Read("max_time_stretch", &o->max_time_stretch);
  section.Read("collapse_duration_fraction", &o->collapse_duration_fraction);
  section.Read("collapse_rho_factor", &o->collapse_rho_factor);
  section.Read("max_collapse_restarts", &o->max_collapse_restarts);
  section.Read("ee_position_tolerance_m", &o->ee_position_tolerance_m);
  section.Read("ee_orientation_tolerance_rad", &o->ee_orientation_tolerance_rad);
  ReadAlm(section.Section("alm"), &o->alm);
  ReadWarmStart(section.Section("warm_start"), &o->warm_start);
  ReadLbfgs(section.Section("lbfgs"), &o->lbfgs);
  ReadObjective(section.Section("objective"), &o->objective);
  ReadFeasibility(section.Section("feasibility"), &o->feasibility);
  section.Finish();
}

}  // namespace topay
