#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tools/topay_bench/bench_options.h"
#include "tools/topay_bench/bench_record.h"
#include "tools/topay_bench/method_summary.h"
#include "tools/topay_bench/summary_report.h"

namespace topay::bench {

/// What a run did.
struct BenchReport {
  BenchRunInfo info;
  std::vector<BenchRecord> records;      ///< In run order (task, then rotation).
  std::vector<MethodSummary> summaries;  ///< In the options' method order.
  std::string tasks_jsonl;               ///< Paths of the files written.
  std::string summary_json;

  /// SummaryMarkdown(summaries, info).
  std::string Markdown() const;
};

/// Called after each task with (tasks done, tasks in all).
using BenchProgress = std::function<void(int done, int total)>;

/// Runs the benchmark (see BenchOptions and RunBenchTask): creates out_dir, writes
/// tasks.jsonl (one line per task and method, bench_record_json.h; flushed after every
/// task, so an interrupted run keeps its finished tasks) and at the end summary.json
/// (summary_report.h). Throws plan::UsageError for bad options (CheckBenchOptions),
/// ConfigError for a missing or malformed robot or planner file (naming it), and
/// std::runtime_error (or ConfigError) for an output that cannot be created or written.
BenchReport RunBench(const BenchOptions& options, const BenchProgress& progress = {});

}  // namespace topay::bench
