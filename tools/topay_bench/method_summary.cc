#include "tools/topay_bench/method_summary.h"

#include <limits>
#include <map>
#include <set>

#include "core/common/sample_statistics.h"

namespace topay::bench {
namespace {

// Tasks solved by every method.
std::set<int> CommonTasks(const std::vector<BenchRecord>& records,
                          const std::vector<std::string>& methods) {
  const std::set<std::string> compared(methods.begin(), methods.end());
  std::map<int, int> solved_by;
  for (const BenchRecord& r : records) {
    if (r.success && compared.count(r.method) != 0) ++solved_by[r.task];
  }
  std::set<int> common;
  for (const auto& [task, count] : solved_by) {
    if (count == static_cast<int>(methods.size())) common.insert(task);
  }
  return common;
}

MethodSummary SummarizeOne(const std::vector<BenchRecord>& records, const std::string& method,
                           const std::set<int>& common) {
  MethodSummary s;
  s.method = method;
  int reachable_successes = 0;
  std::vector<double> tp_ok, td_ok, tp_all, tp_common, td_common, map_ms;
  for (const BenchRecord& r : records) {
    if (r.method != method) continue;
    ++s.tasks;
    tp_all.push_back(r.tp_ms());
    s.unreachable_tasks += r.base_unreachable ? 1 : 0;
    map_ms.push_back(r.map_ms);
    if (!r.success) {
      s.failures.Add(r.failure == FailureCategory::kNone ? FailureCategory::kOther : r.failure);
      continue;
    }
    ++s.successes;
    reachable_successes += r.base_unreachable ? 0 : 1;
    tp_ok.push_back(r.tp_ms());
    td_ok.push_back(r.duration_s);
    if (common.count(r.task) != 0) {
      tp_common.push_back(r.tp_ms());
      td_common.push_back(r.duration_s);
    }
  }
  s.success_rate = s.tasks > 0 ? static_cast<double>(s.successes) / s.tasks : 0.0;
  const int reachable = s.tasks - s.unreachable_tasks;
  s.success_rate_reachable = reachable > 0 ? static_cast<double>(reachable_successes) / reachable
                                           : std::numeric_limits<double>::quiet_NaN();
  s.tp_ms_mean = Mean(tp_ok);
  s.tp_ms_median = Median(tp_ok);
  s.tp_ms_p95 = NearestRankQuantile(tp_ok, 0.95);
  s.tp_ms_median_all = Median(tp_all);
  s.td_s_mean = Mean(td_ok);
  s.common_tasks = static_cast<int>(common.size());
  s.common_tp_ms_mean = Mean(tp_common);
  s.common_td_s_mean = Mean(td_common);
  s.map_ms_mean = Mean(map_ms);
  return s;
}

}  // namespace

std::vector<MethodSummary> SummarizeMethods(const std::vector<BenchRecord>& records,
                                            const std::vector<std::string>& methods) {
  const std::set<int> common = CommonTasks(records, methods);
  std::vector<MethodSummary> summaries;
  for (const std::string& method : methods) {
    summaries.push_back(SummarizeOne(records, method, common));
  }
  return summaries;
}

}  // namespace topay::bench
