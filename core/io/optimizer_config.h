#pragma once

#include "core/io/yaml_section.h"
#include "core/optimization/trajectory_optimizer.h"

namespace topay {

/// Reads the `optimizer` section of the planner YAML (config/planner/topay.yaml documents
/// every field) into TrajectoryOptimizerOptions: the top-level run options, and the
/// sub-sections alm, warm_start, lbfgs, objective (with jerk_weights and penalties) and
/// feasibility. Absent fields keep their defaults; unknown or malformed ones throw
/// ConfigError naming the dotted field. The values are checked by the caller
/// (CheckTrajectoryOptimizerOptions and the optimizer's constructor).
void ReadOptimizerOptions(YamlSection section, TrajectoryOptimizerOptions* options);

}  // namespace topay
