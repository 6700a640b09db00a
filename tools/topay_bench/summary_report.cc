#include "tools/topay_bench/summary_report.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace topay::bench {
namespace {

using Json = nlohmann::ordered_json;

Json Number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

std::string Cell(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

Json FailuresJson(const FailureTally& tally) {
  Json json = Json::object();
  for (const FailureCategory category : kFailureCategories) {
    json[std::string(FailureCategoryName(category))] = tally.Count(category);
  }
  return json;
}

Json MethodJson(const MethodSummary& s, const BenchRunInfo& info) {
  return Json{{"method", s.method},
              {"scene", info.scene},
              {"range", info.range},
              {"cell", CellName(info.scene, info.range, info.tight)},
              {"tight", info.tight},
              {"tight_clearance_max_m",
               info.tight ? Json(info.tight_clearance_max_m) : Json(nullptr)},
              {"seed", info.seed},
              {"tasks", s.tasks},
              {"successes", s.successes},
              {"success_rate", s.success_rate},
              {"unreachable_tasks", s.unreachable_tasks},
              {"success_rate_reachable", Number(s.success_rate_reachable)},
              {"failures_by_reason", FailuresJson(s.failures)},
              {"tp_ms_mean", Number(s.tp_ms_mean)},
              {"tp_ms_median", Number(s.tp_ms_median)},
              {"tp_ms_p95", Number(s.tp_ms_p95)},
              {"tp_ms_median_all", Number(s.tp_ms_median_all)},
              {"td_s_mean", Number(s.td_s_mean)},
              {"common_tasks", s.common_tasks},
              {"common_tp_ms_mean", Number(s.common_tp_ms_mean)},
              {"common_td_s_mean", Number(s.common_td_s_mean)},
              {"map_ms_mean", Number(s.map_ms_mean)},
              {"threads", info.threads},
              {"time_limit_ms", info.time_limit_ms},
              {"use_hint", info.use_hint},
              {"base_limits", info.base_limits},
              {"planner_config", info.planner_config},
              {"sensed_map", info.sensed_map.empty() ? Json(nullptr) : Json(info.sensed_map)},
              {"sensed_unknown", info.sensed_map.empty() ? Json(nullptr) : Json(info.sensed_unknown)},
              {"sensed_margin_m", info.sensed_map.empty() ? Json(nullptr) : Json(info.sensed_margin_m)},
              {"tp_statistics",
               "tp_ms_* and td_s_mean over successful tasks; tp_ms_median_all over all tasks; "
               "common_* over the tasks every method solved"}};
}

}  // namespace

nlohmann::ordered_json SummaryJson(const std::vector<MethodSummary>& summaries,
                                   const BenchRunInfo& info) {
  Json array = Json::array();
  for (const MethodSummary& s : summaries) array.push_back(MethodJson(s, info));
  return array;
}

std::string SummaryMarkdown(const std::vector<MethodSummary>& summaries, const BenchRunInfo& info) {
  std::ostringstream out;
  out << "| method | tasks | S.R. (%) | unreachable | S.R. reachable (%) | T.P. mean (ms) "
         "| T.P. median (ms) | T.P. p95 (ms) | T.D. mean (s) | common T.P. mean (ms) "
         "| common T.D. mean (s) |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const MethodSummary& s : summaries) {
    out << "| " << s.method << " | " << s.tasks << " | " << Cell(100.0 * s.success_rate, 1) << " | "
        << s.unreachable_tasks << " | " << Cell(100.0 * s.success_rate_reachable, 1) << " | "
        << Cell(s.tp_ms_mean, 1) << " | " << Cell(s.tp_ms_median, 1) << " | "
        << Cell(s.tp_ms_p95, 1) << " | " << Cell(s.td_s_mean, 2) << " | "
        << Cell(s.common_tp_ms_mean, 1) << " | " << Cell(s.common_td_s_mean, 2) << " |\n";
  }
  out << "\n";
  for (const MethodSummary& s : summaries) {
    out << s.method << " failures by reason: " << s.failures.Text() << "\n";
  }
  const int common = summaries.empty() ? 0 : summaries.front().common_tasks;
  out << "\n"
      << "Cell " << CellName(info.scene, info.range, info.tight) << ": " << info.scene << ", "
      << info.range << " range"
      << (info.tight ? ", tight tasks (start and goal within " +
                           Cell(100.0 * info.tight_clearance_max_m, 1) + " cm of a box)"
                     : "")
      << ", seed "
      << info.seed << ", " << info.threads
      << " thread(s), time limit " << Cell(info.time_limit_ms, 0) << " ms, " << info.base_limits
      << " base limits, hint " << (info.use_hint ? "on" : "off")
      << ". T.P. and T.D. over each method's successful tasks; common: the " << common
      << " task(s) every method solved. Unreachable: tasks certified unsolvable (no motion "
         "of the rigid lower body brings the target within the arm's reach, a planner-"
         "independent test); S.R. reachable excludes them.\n";
  if (!info.sensed_map.empty()) {
    out << "Methods <m>@sensed planned on the task's scene as the simulated LiDAR mapped it from the "
        << info.sensed_map << " tour (unknown voxels " << info.sensed_unknown << ", an extra obstacle margin of "
        << Cell(100.0 * info.sensed_margin_m, 1) << " cm), and count only if the validator also accepts the trajectory on the exact scene; "
           "their map_ms is the mapping plus the fields.\n";
  }
  return out.str();
}

}  // namespace topay::bench
