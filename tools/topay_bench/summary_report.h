#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/topay_bench/method_summary.h"

namespace topay::bench {

/// The run-wide settings repeated in every object of summary.json.
struct BenchRunInfo {
  std::string scene;
  std::string range;
  bool tight = false;  ///< Tight tasks (--tight).
  /// Tight tasks: the generator's bound on each end's obstacle clearance (m).
  double tight_clearance_max_m = 0.0;
  std::uint64_t seed = 0;
  int threads = 0;  ///< Workers actually used (0 resolved to the hardware's count).
  double time_limit_ms = 0.0;
  bool use_hint = true;
  std::string base_limits;  ///< "benchmark" | "robot".
  std::string planner_config;
  /// Sensed maps (--sensed-map): the tour ("line" | "tour") and the unknown-voxel policy;
  /// empty: none.
  std::string sensed_map;
  std::string sensed_unknown;
  double sensed_margin_m = 0.0;  ///< The planner's extra obstacle margin on sensed maps.
};

// summary.json: a JSON array, one object per method, in the run's method order:
//   {"method", "scene", "range", "cell" ("tables medium tight"), "tight",
//    "tight_clearance_max_m" (null unless tight), "seed", "tasks",
//    "successes", "success_rate" (0..1), "unreachable_tasks", "success_rate_reachable",
//    "failures_by_reason": {"start_refused": n, ..., "other": n} (every FailureCategoryName),
//    "tp_ms_mean", "tp_ms_median", "tp_ms_p95", "tp_ms_median_all", "td_s_mean",
//    "common_tasks", "common_tp_ms_mean", "common_td_s_mean", "map_ms_mean",
//    "threads", "time_limit_ms", "use_hint", "base_limits", "planner_config",
//    "sensed_map", "sensed_unknown" and "sensed_margin_m" (null without sensed maps),
//    "tp_statistics": "..."}  (see MethodSummary; NaN figures are null).

/// The summary.json array.
nlohmann::ordered_json SummaryJson(const std::vector<MethodSummary>& summaries,
                                   const BenchRunInfo& info);

/// A Markdown table, one row per method: tasks, S.R. (%), T.P. mean / median / p95 (ms),
/// T.D. mean (s), common T.P. mean (ms) and T.D. mean (s); then one line per method with its
/// failures by reason ("topay failures by reason: 3 start refused, 1 no goal"); then a line
/// naming the cell and saying what the columns cover (successful tasks; the common tasks).
/// "-" for NaN.
std::string SummaryMarkdown(const std::vector<MethodSummary>& summaries, const BenchRunInfo& info);

}  // namespace topay::bench
