#include "core/io/planner_config.h"

#include <exception>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/optimizer_config.h"
#include "core/io/yaml_section.h"

namespace topay {
namespace {

void ReadBaseLimits(YamlSection section, BaseLimits* limits) {
  section.Read("v_max_mps", &limits->v_max_mps);
  section.Read("a_max_mps2", &limits->a_max_mps2);
  section.Read("omega_max_radps", &limits->omega_max_radps);
  section.Read("beta_max_radps2", &limits->beta_max_radps2);
  section.Finish();
}

void ReadPlanner(YamlSection section, WholeBodyPlannerOptions* o) {
  section.Read("early_termination_window_s", &o->early_termination_window_s);
  section.Read("sequential", &o->sequential);
  section.Read("num_threads", &o->num_threads);
  section.Read("time_limit_s", &o->time_limit_s);
  section.Read("max_candidates", &o->max_candidates);
  YamlSection limits = section.Section("base_limits");
  if (limits.present()) {  // any field given: the rest from BaseLimits' defaults
    BaseLimits base_limits = o->base_limits.value_or(BaseLimits{});
    ReadBaseLimits(limits, &base_limits);
    o->base_limits = base_limits;
  }
  section.Finish();
}

BasePathMode ParseMode(const std::string& text, const YamlSection& section) {
  if (text == "topological_with_jps") return BasePathMode::kTopologicalWithJps;
  if (text == "topological_only") return BasePathMode::kTopologicalOnly;
  if (text == "jps_only") return BasePathMode::kJpsOnly;
  throw ConfigError(section.source(), section.FieldPath("mode"),
                    "expected topological_with_jps, topological_only or jps_only, got '" +
                        text + "'");
}

void ReadTopology(YamlSection section, TopologicalPathSearchOptions* o) {
  std::string mode;
  section.Read("mode", &mode);
  if (!mode.empty()) o->mode = ParseMode(mode, section);
  section.Read("clearance_m", &o->clearance_m);
  YamlSection prm = section.Section("prm");
  prm.Read("sample_margin_length_m", &o->prm.sample_margin_length_m);
  prm.Read("sample_half_width_m", &o->prm.sample_half_width_m);
  prm.Read("max_samples", &o->prm.max_samples);
  prm.Read("max_time_s", &o->prm.max_time_s);
  prm.Finish();
  YamlSection enumeration = section.Section("enumeration");
  enumeration.Read("max_raw_paths", &o->enumeration.max_raw_paths);
  enumeration.Read("keep_fewest_hops", &o->enumeration.keep_fewest_hops);
  enumeration.Finish();
  YamlSection shortcut = section.Section("shortcut");
  shortcut.Read("resample_step_m", &o->shortcut.resample_step_m);
  shortcut.Read("max_passes", &o->shortcut.max_passes);
  shortcut.Finish();
  YamlSection pruning = section.Section("pruning");
  pruning.Read("resolution_m", &o->pruning.resolution_m);
  pruning.Read("max_length_ratio", &o->pruning.max_length_ratio);
  pruning.Read("max_paths", &o->pruning.max_paths);
  pruning.Read("visibility_slack_m", &o->pruning.visibility_slack_m);
  pruning.Finish();
  YamlSection jps = section.Section("jps");
  jps.Read("shortcut", &o->jps.shortcut);
  jps.Finish();
  section.Finish();
}

void ReadFrontEnd(YamlSection section, FrontEndOptions* o) {
  section.Read("max_goal_attempts", &o->max_goal_attempts);
  section.Read("fallback_base_clearance_m", &o->fallback_base_clearance_m);
  section.Read("reachable_goal_search", &o->reachable_goal_search);
  section.Read("improvement_window_s", &o->improvement_window_s);
  section.Read("acquisition_budget_s", &o->acquisition_budget_s);
  section.Read("num_threads", &o->num_threads);
  section.Read("seed", &o->seed);
  YamlSection goal = section.Section("goal");
  goal.Read("max_candidates", &o->goal.max_candidates);
  goal.Read("travel_weight", &o->goal.travel_weight);
  goal.Read("yaw_weight_m_per_rad", &o->goal.yaw_weight_m_per_rad);
  goal.Read("clearance_weight", &o->goal.clearance_weight);
  goal.Read("clearance_saturation_m", &o->goal.clearance_saturation_m);
  goal.Read("hint_first", &o->goal.hint_first);
  goal.Finish();
  YamlSection ik = section.Section("ik");
  ik.Read("max_solutions", &o->ik.max_solutions);
  ik.Read("time_budget_s", &o->ik.time_budget_s);
  ik.Read("position_tolerance_m", &o->ik.position_tolerance_m);
  ik.Read("orientation_tolerance_rad", &o->ik.orientation_tolerance_rad);
  ik.Read("max_base_candidates", &o->ik.max_base_candidates);
  ik.Read("restarts_per_base", &o->ik.restarts_per_base);
  ik.Finish();
  ReadTopology(section.Section("topology"), &o->topology);
  YamlSection discretisation = section.Section("discretisation");
  discretisation.Read("delta_l_m", &o->discretisation.delta_l_m);
  discretisation.Read("max_turn_step_rad", &o->discretisation.max_turn_step_rad);
  discretisation.Finish();
  YamlSection rrt = section.Section("rrt");
  rrt.Read("time_budget_s", &o->rrt.time_budget_s);
  rrt.Read("stop_at_first_solution", &o->rrt.stop_at_first_solution);
  rrt.Read("goal_bias", &o->rrt.goal_bias);
  rrt.Read("stow_bias", &o->rrt.stow_bias);
  rrt.Read("rewire_radius_rad", &o->rrt.rewire_radius_rad);
  rrt.Read("max_neighbours", &o->rrt.max_neighbours);
  rrt.Read("max_informed_draws", &o->rrt.max_informed_draws);
  rrt.Read("max_nodes", &o->rrt.max_nodes);
  rrt.Finish();
  YamlSection validity = section.Section("validity");
  validity.Read("self_margin_m", &o->validity.self_margin_m);
  validity.Read("max_edge_step_m", &o->validity.max_edge_step_m);
  validity.Read("max_edge_step_rad", &o->validity.max_edge_step_rad);
  validity.Finish();
  section.Finish();
}

void ReadValidator(YamlSection section, TrajectoryValidatorOptions* o) {
  section.Read("sample_period_s", &o->sample_period_s);
  section.Read("limit_tolerance", &o->limit_tolerance);
  section.Read("ee_position_tolerance_m", &o->ee_position_tolerance_m);
  section.Read("ee_orientation_tolerance_rad", &o->ee_orientation_tolerance_rad);
  section.Read("obstacle_margin_m", &o->obstacle_margin_m);
  section.Read("self_margin_m", &o->self_margin_m);
  section.Finish();
}

}  // namespace

WholeBodyPlannerOptions ParsePlannerOptions(const std::string& yaml_text,
                                            const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source, "", std::string("malformed YAML: ") + e.what());
  }
  WholeBodyPlannerOptions options;
  YamlSection top(root, source);
  ReadPlanner(top.Section("planner"), &options);
  ReadFrontEnd(top.Section("front_end"), &options.front_end);
  ReadOptimizerOptions(top.Section("optimizer"), &options.optimizer);
  ReadValidator(top.Section("validator"), &options.validator);
  top.Finish();
  try {
    CheckWholeBodyPlannerOptions(options);
    CheckTrajectoryOptimizerOptions(options.optimizer);
    CheckFrontEndOptions(options.front_end);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(source, "", e.what());
  }
  return options;
}

WholeBodyPlannerOptions LoadPlannerOptions(const std::string& path) {
  return ParsePlannerOptions(ReadBoundedTextFile(path, kMaxConfigFileBytes, "planner YAML"), path);
}

}  // namespace topay
