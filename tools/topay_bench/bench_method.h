#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/planner/whole_body_planner_options.h"

namespace topay::bench {

/// The planner variants topay-bench compares, each an option change of the loaded planner
/// options (ApplyBenchMethod).
enum class BenchMethod {
  kTopay,       ///< "topay": the options as loaded.
  kJpsOnly,     ///< "jps-only": front_end.topology.mode = kJpsOnly (Table I ablation).
  kSequential,  ///< "sequential": the planner's `sequential` ablation (no early termination).
  /// "flatness": the REMANI-style baseline: the optimizer's kFlatness parameterisation on a
  /// single greedy base path (front end JPS only, max_candidates = 1).
  kFlatness,
};

/// "topay", "jps-only", "sequential" or "flatness".
std::string_view BenchMethodName(BenchMethod method);
/// Inverse of BenchMethodName; nullopt for anything else.
std::optional<BenchMethod> ParseBenchMethod(std::string_view name);
/// Every method, in enum order.
std::vector<BenchMethod> AllBenchMethods();

/// Changes `options` (loaded from the planner YAML) into the method's planner options; touches
/// only the fields named in BenchMethod's documentation.
void ApplyBenchMethod(BenchMethod method, WholeBodyPlannerOptions* options);

}  // namespace topay::bench
