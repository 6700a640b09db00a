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
  std::uint64_t seed = 0;
  int threads = 0;  ///< Workers actually used (0 resolved to the hardware's count).
  double time_limit_ms = 0.0;
  bool use_hint = true;
  std::string base_limits;  ///< "benchmark" | "robot".
  std::string planner_config;
};

// summary.json: a JSON array, one object per method, in the run's method order:
//   {"method", "scene", "range", "seed", "tasks", "successes", "success_rate" (0..1),
//    "tp_ms_mean", "tp_ms_median", "tp_ms_p95", "tp_ms_median_all", "td_s_mean",
//    "common_tasks", "common_tp_ms_mean", "common_td_s_mean", "map_ms_mean",
//    "threads", "time_limit_ms", "use_hint", "base_limits", "planner_config",
//    "tp_statistics": "..."}  (see MethodSummary; NaN figures are null).

/// The summary.json array.
nlohmann::ordered_json SummaryJson(const std::vector<MethodSummary>& summaries,
                                   const BenchRunInfo& info);

/// A Markdown table, one row per method: tasks, S.R. (%), T.P. mean / median / p95 (ms),
/// T.D. mean (s), common T.P. mean (ms) and T.D. mean (s); then a line saying what the
/// columns cover (successful tasks; the common tasks). "-" for NaN.
std::string SummaryMarkdown(const std::vector<MethodSummary>& summaries, const BenchRunInfo& info);

}  // namespace topay::bench
