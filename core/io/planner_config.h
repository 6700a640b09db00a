#pragma once

#include <string>

#include "core/planner/whole_body_planner_options.h"

namespace topay {

/// Loads the planner's options from YAML (config/planner/topay.yaml is the shipped file and
/// documents every field). Sections: `planner` (WholeBodyPlannerOptions' own fields and an
/// optional `base_limits`), `front_end` (FrontEndOptions, with goal, ik, topology (prm,
/// enumeration, shortcut, pruning, jps), discretisation, rrt, validity), `optimizer`
/// (TrajectoryOptimizerOptions: core/io/optimizer_config.h) and `validator`
/// (TrajectoryValidatorOptions). Every field is optional: an absent one keeps the struct's
/// default. Throws ConfigError naming the file and the dotted field for a malformed value or
/// an unknown field, and for values the options' own checks reject: every options struct the
/// file sets is checked here (planner, base limits, goal, IK, topology, discretisation, RRT,
/// validity, front end, L-BFGS, warm start, penalties, optimizer, validator), so that a value
/// that would fail when the planner is built or run fails at load instead. LoadPlannerOptions
/// reads at most kMaxConfigFileBytes (core/io/bounded_text_file.h); a directory is an error.
WholeBodyPlannerOptions LoadPlannerOptions(const std::string& path);
WholeBodyPlannerOptions ParsePlannerOptions(const std::string& yaml_text,
                                            const std::string& source);

}  // namespace topay
