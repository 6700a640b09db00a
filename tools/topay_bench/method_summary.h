#pragma once

#include <string>
#include <vector>

#include "tools/topay_bench/bench_record.h"

namespace topay::bench {

/// One method's figures over a run (one object of summary.json). As in the paper, the T.P.
/// (planning time, ms: WholeBodyPlanResult::timings.total_ms) and T.D. (trajectory
/// duration, s) statistics are over the method's SUCCESSFUL tasks only; tp_ms_median_all is
/// the median T.P. over all its tasks. "common" figures are over the tasks that every
/// compared method solved, so that methods compare on the same tasks. NaN (null in JSON):
/// no task to average over.
struct MethodSummary {
  std::string method;
  int tasks = 0;  ///< Tasks run by the method.
  int successes = 0;
  double success_rate = 0.0;  ///< successes / tasks, in [0, 1].
  /// Tasks certified unsolvable (BenchRecord::base_unreachable), and the success rate over the
  /// others: their successes / (tasks - unreachable_tasks) (NaN when none is left).
  int unreachable_tasks = 0;
  double success_rate_reachable = 0.0;
  double tp_ms_mean = 0.0;
  double tp_ms_median = 0.0;
  double tp_ms_p95 = 0.0;  ///< Nearest rank (bench_statistics.h).
  double tp_ms_median_all = 0.0;
  double td_s_mean = 0.0;
  int common_tasks = 0;  ///< Tasks every method solved (the same for every method).
  double common_tp_ms_mean = 0.0;
  double common_td_s_mean = 0.0;
  double map_ms_mean = 0.0;  ///< Distance field build time (not in T.P.), over all tasks.
  /// The method's failed tasks by category (BenchRecord::failure; a failure without a
  /// category counts as kOther): failures.Total() == tasks - successes.
  FailureTally failures;
};

/// The summaries of `methods` (in that order) from the records of a run (any order; each
/// (task, method) at most once). A task counts as common when every method has a successful
/// record for it.
std::vector<MethodSummary> SummarizeMethods(const std::vector<BenchRecord>& records,
                                            const std::vector<std::string>& methods);

}  // namespace topay::bench
