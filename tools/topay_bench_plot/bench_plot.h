#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/viz/image.h"

namespace topay::bench_plot {

/// A missing or malformed input file; the message names the file (and line) and what is wrong.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One method's entry of a run's summary.json (README, Benchmark).
struct SummaryEntry {
  std::string method;
  std::string scene;
  std::string range;
  int tasks = 0;
  double success_rate = 0.0;  ///< In [0, 1].
};

/// One line of a run's tasks.jsonl: a method on a task.
struct TaskLine {
  std::string scene;
  std::string range;
  std::string method;
  bool success = false;
  double total_ms = 0.0;                ///< timings_ms.total, T.P.
  std::optional<double> duration_s;     ///< T.D.; null in the file for a failure.
  double base_distance_m = 0.0;
};

struct BenchRuns {
  std::vector<SummaryEntry> summaries;
  std::vector<TaskLine> lines;
};

/// Reads summary.json and tasks.jsonl of every run folder (topay-bench --out), in order.
/// Throws InputError naming the file (and line number) for a missing file, malformed JSON or a
/// missing or mistyped field.
BenchRuns ReadBenchRuns(const std::vector<std::string>& run_dirs);

/// Success rate (%) per scene and range, one bar per method (grouped); a method that did not
/// run a cell has no bar there.
viz::Image RenderSuccessRate(const std::vector<SummaryEntry>& summaries);

/// Planning time T.P. (ms) of the successful tasks per method, one box-plot panel per scene and
/// range (box: quartiles, line: median, whiskers: the farthest points within 1.5 IQR, dots:
/// beyond).
viz::Image RenderPlanningTime(const std::vector<TaskLine>& lines);

/// Trajectory duration T.D. (s) against the straight-line base distance (m) of the successful
/// tasks, one colour per method.
viz::Image RenderDurationVsDistance(const std::vector<TaskLine>& lines);

/// The quartiles and whiskers a box of RenderPlanningTime shows (values need not be sorted;
/// quantiles interpolate linearly between order statistics, as numpy's default).
struct BoxStats {
  double q1 = 0.0, median = 0.0, q3 = 0.0;
  double whisker_low = 0.0, whisker_high = 0.0;
  std::vector<double> outliers;
};
BoxStats ComputeBoxStats(std::vector<double> values);

/// Writes success_rate.png, planning_time.png and duration_vs_distance.png into out_dir
/// (created). Throws std::runtime_error naming the folder or file if it cannot be written.
void WriteBenchPlots(const BenchRuns& runs, const std::string& out_dir);

}  // namespace topay::bench_plot
