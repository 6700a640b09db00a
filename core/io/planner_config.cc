#include "core/io/planner_config.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/optimizer_config.h"
#include "core/io/yaml_section.h"
#include "core/optimization/lbfgs_solve.h"
#include "core/optimization/sample_penalties.h"
#include "core/optimization/warm_start.h"
#include "core/planning/arm_rrt_star.h"
#include "core/planning/discrete_se2.h"
#include "core/planning/goal_candidates.h"
#include "core/planning/topological_path_search.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/whole_body_ik.h"
#include "core/validate/limit_ratios.h"
#include "core/validate/trajectory_validator.h"

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
  YamlSection retry = section.Section("retry");
  retry.Read("max_rounds", &o->retry.max_rounds);
  retry.Read("min_time_left_s", &o->retry.min_time_left_s);
  retry.Read("clearance_step_m", &o->retry.clearance_step_m);
  retry.Read("round_time_share", &o->retry.round_time_share);
  retry.Read("arm_budget_growth", &o->retry.arm_budget_growth);
  retry.Read("warm_start_slowdown", &o->retry.warm_start_slowdown);
  retry.Finish();
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
  section.Read("other_way_turn_min_rad", &o->other_way_turn_min_rad);
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
  goal.Read("standing_candidate", &o->goal.standing_candidate);
  goal.Finish();
  YamlSection ik = section.Section("ik");
  ik.Read("max_solutions", &o->ik.max_solutions);
  ik.Read("time_budget_s", &o->ik.time_budget_s);
  ik.Read("position_tolerance_m", &o->ik.position_tolerance_m);
  ik.Read("orientation_tolerance_rad", &o->ik.orientation_tolerance_rad);
  ik.Read("max_base_candidates", &o->ik.max_base_candidates);
  ik.Read("restarts_per_base", &o->ik.restarts_per_base);
  ik.Finish();
  YamlSection retry = section.Section("goal_retry");
  retry.Read("enabled", &o->goal_retry.enabled);
  retry.Read("max_base_candidates", &o->goal_retry.max_base_candidates);
  retry.Read("restarts_per_base", &o->goal_retry.restarts_per_base);
  retry.Read("time_budget_s", &o->goal_retry.time_budget_s);
  retry.Read("max_total_iterations", &o->goal_retry.max_total_iterations);
  retry.Finish();
  // The zones' margins are the validator's (set by the planner), so only the radius is read.
  YamlSection zones = section.Section("exact_zones");
  zones.Read("radius_m", &o->exact_zones.radius_m);
  zones.Finish();
  YamlSection escape = section.Section("base_escape");
  escape.Read("max_distance_m", &o->base_escape.max_distance_m);
  escape.Read("step_m", &o->base_escape.step_m);
  escape.Read("num_directions", &o->base_escape.num_directions);
  escape.Read("check_step_m", &o->base_escape.check_step_m);
  escape.Read("route_step_m", &o->base_escape.route_step_m);
  escape.Finish();
  ReadTopology(section.Section("topology"), &o->topology);
  YamlSection discretisation = section.Section("discretisation");
  discretisation.Read("delta_l_m", &o->discretisation.delta_l_m);
  discretisation.Read("max_turn_step_rad", &o->discretisation.max_turn_step_rad);
  discretisation.Finish();
  YamlSection dwell = section.Section("arm_dwell");
  dwell.Read("travel_time_factor", &o->arm_dwell.travel_time_factor);
  dwell.Read("min_time_s", &o->arm_dwell.min_time_s);
  dwell.Read("step_s", &o->arm_dwell.step_s);
  dwell.Finish();
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

// The dotted paths of the values the file gives under `node` (maps descended), e.g.
// "prm.max_time_s" under front_end.topology.
void CollectFields(const YAML::Node& node, const std::string& prefix,
                   std::vector<std::string>* fields) {
  if (!node.IsMap()) {
    if (!prefix.empty()) fields->push_back(prefix);
    return;
  }
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>("?");
    CollectFields(entry.second, prefix.empty() ? key : prefix + "." + key, fields);
  }
}

bool IsWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Where `key` occurs in `message` as a name: not followed by a name character, and preceded by
// none or by '_' / '.' (the options' own spellings: "alm_rho_initial", "options.goal_bias").
std::size_t NamePosition(const std::string& message, const std::string& key) {
  for (std::size_t at = message.find(key); at != std::string::npos;
       at = message.find(key, at + 1)) {
    const std::size_t end = at + key.size();
    const bool starts = at == 0 || !std::isalnum(static_cast<unsigned char>(message[at - 1]));
    const bool ends = end == message.size() || !IsWordChar(message[end]);
    if (starts && ends) return at;
  }
  return std::string::npos;
}

// The YAML field a failed option check is about: of the fields the file gives under `section`,
// the one whose key the check's message names first (only a field the file sets can be out of
// range: the defaults pass). The section itself if the message names none of them.
std::string FieldNamedBy(const YAML::Node& root, const std::string& section,
                         const std::string& message) {
  YAML::Node node = root;
  for (std::size_t begin = 0; begin <= section.size();) {
    const std::size_t dot = std::min(section.find('.', begin), section.size());
    if (!node.IsMap()) return section;
    node = node[section.substr(begin, dot - begin)];
    begin = dot + 1;
  }
  std::vector<std::string> fields;
  CollectFields(node, "", &fields);
  std::string best;
  std::size_t best_at = std::string::npos;
  for (const std::string& field : fields) {
    const std::size_t dot = field.rfind('.');
    const std::string key = dot == std::string::npos ? field : field.substr(dot + 1);
    const std::size_t at = NamePosition(message, key);
    if (at < best_at || (at == best_at && at != std::string::npos && field.size() > best.size())) {
      best = field;
      best_at = at;
    }
  }
  return best_at == std::string::npos ? section : section + "." + best;
}

// The option checks of every struct the file configures, finest section first, so that the
// ConfigError names the field: the values are checked where they are read, not when the
// planner is built (a bad value is a config error, exit 1, not a failed plan).
void CheckOptions(const YAML::Node& root, const std::string& source,
                  const WholeBodyPlannerOptions& o) {
  const auto throwing = [](auto check) {
    return [check]() -> std::string {
      try {
        check();
      } catch (const std::invalid_argument& e) {
        return e.what();
      }
      return {};
    };
  };
  const FrontEndOptions& f = o.front_end;
  const std::pair<const char*, std::function<std::string()>> checks[] = {
      {"planner.base_limits", throwing([&] {
         if (o.base_limits) CheckKinematicLimits(*o.base_limits, JointLimits{}, 0);
       })},
      {"planner", throwing([&] { CheckWholeBodyPlannerOptions(o); })},
      {"front_end.goal", throwing([&] { CheckGoalCandidatesOptions(f.goal); })},
      {"front_end.ik", throwing([&] { CheckWholeBodyIkOptions(f.ik); })},
      {"front_end.topology", [&] { return CheckTopologicalPathSearchOptions(f.topology); }},
      {"front_end.discretisation", throwing([&] { CheckDiscreteSE2Options(f.discretisation); })},
      {"front_end.arm_dwell", throwing([&] { CheckArmDwellOptions(f.arm_dwell); })},
      {"front_end.rrt", [&] { return CheckArmRrtStarOptions(f.rrt); }},
      {"front_end.validity", throwing([&] { CheckWholeBodyValidityOptions(f.validity); })},
      {"front_end", throwing([&] { CheckFrontEndOptions(f); })},
      {"optimizer.lbfgs", throwing([&] { CheckLbfgsOptions(o.optimizer.lbfgs); })},
      {"optimizer.warm_start", throwing([&] { CheckWarmStartOptions(o.optimizer.warm_start); })},
      {"optimizer.objective.penalties",
       throwing([&] { CheckSamplePenaltyOptions(o.optimizer.objective.penalties); })},
      {"optimizer", throwing([&] { CheckTrajectoryOptimizerOptions(o.optimizer); })},
      {"validator", throwing([&] { CheckTrajectoryValidatorOptions(o.validator); })},
  };
  for (const auto& [section, check] : checks) {
    const std::string problem = check();
    if (!problem.empty()) throw ConfigError(source, FieldNamedBy(root, section, problem), problem);
  }
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
  CheckOptions(root, source, options);
  return options;
}

WholeBodyPlannerOptions LoadPlannerOptions(const std::string& path) {
  return ParsePlannerOptions(ReadBoundedTextFile(path, kMaxConfigFileBytes, "planner YAML"), path);
}

}  // namespace topay
