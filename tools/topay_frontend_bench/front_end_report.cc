#include "tools/topay_frontend_bench/front_end_report.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "core/common/sample_statistics.h"

namespace topay::frontend_bench {
namespace {

std::string Fmt(double v, int digits = 1) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << v;
  return out.str();
}

// "median / p95" of a sample (nearest rank).
std::string MedianP95(const std::vector<double>& values) {
  return Fmt(NearestRankQuantile(values, 0.5)) + " / " + Fmt(NearestRankQuantile(values, 0.95));
}

std::string Percent(int part, int whole) {
  const double share = whole > 0 ? 100.0 * part / whole : std::nan("");
  return Fmt(share) + " % (" + std::to_string(part) + "/" + std::to_string(whole) + ")";
}

void WriteTable(const FrontEndBenchOptions& o, const FrontEndTally& t, std::ostream& out) {
  out << "| scene | range | tasks | topo search ms (median / p95) | classes (mean) | "
         "base paths incl. JPS (mean) | RRT* first solution ms (median / p95) | "
         "RRT* success per path | front end ms (median / p95) | tasks with a path | "
         "reachable tasks with a path |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n"
      << "| " << o.scene << (o.jps_only ? " (JPS only)" : "") << " | " << o.range << " | "
      << t.tasks << " | " << MedianP95(t.topology_ms) << " | " << Fmt(Mean(t.classes), 2)
      << " | " << Fmt(Mean(t.base_paths), 2) << " | " << MedianP95(t.rrt_first_ms) << " | "
      << Percent(t.jobs_succeeded, t.jobs_finished) << " | " << MedianP95(t.total_ms) << " | "
      << Percent(t.tasks_ok, t.tasks) << " | "
      << Percent(t.tasks_ok - t.unreachable_ok, t.tasks - t.unreachable) << " |\n\n";
}

void WriteNotes(const FrontEndTally& t, std::ostream& out) {
  out << "Reachable: tasks not certified unsolvable by the rigid lower body's connectivity "
         "to the target's reach disc (core/planning/base_reachability.h); certified: "
      << t.unreachable << ", of which given a path (must be 0): " << t.unreachable_ok << ".\n";
  out << "Goal stage ms (median / p95): " << MedianP95(t.goal_ms)
      << ". Jobs cancelled by the improvement window or budget (not counted in the per-path "
         "rate): "
      << t.jobs_cancelled << ". Paths: " << t.paths
      << ", failing the exact check: " << t.paths_failing_exact_check << ". Status counts:";
  for (const auto& [status, count] : t.statuses) out << " " << status << " " << count;
  out << ".\n";
  out << "Stage medians (ms), last search of each task: PRM "
      << Fmt(NearestRankQuantile(t.prm_ms, 0.5)) << ", DFS "
      << Fmt(NearestRankQuantile(t.dfs_ms, 0.5)) << ", shortcut "
      << Fmt(NearestRankQuantile(t.shortcut_ms, 0.5)) << ", UVD "
      << Fmt(NearestRankQuantile(t.pruning_ms, 0.5)) << ", JPS "
      << Fmt(NearestRankQuantile(t.jps_ms, 0.5)) << "; arm stage "
      << MedianP95(t.acquisition_ms) << " (median / p95). Tasks needing the fallback base "
      << "search: " << t.fallback_searches << ", the reachable-goal search: "
      << t.reachable_goal_searches << ".\n";
  for (const std::string& failure : t.exact_failures) out << "  exact check: " << failure << "\n";
}

}  // namespace

void WriteFrontEndReport(const FrontEndBenchOptions& o, const FrontEndTally& t,
                         std::ostream& out) {
  WriteTable(o, t, out);
  WriteNotes(t, out);
}

}  // namespace topay::frontend_bench
