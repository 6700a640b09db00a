#include "core/planning/topological_path_search.h"

#include <cmath>

#include "core/common/stopwatch.h"
#include "core/planning/base_free_space.h"

namespace topay {
namespace {

using Status = TopologicalPathSearchResult::Status;
TopologicalPathSearchResult Fail(TopologicalPathSearchResult result, Status status,
                                 std::string reason) {
  result.status = status;
  result.reason = std::move(reason);
  result.paths.clear();
  return result;
}


// {index of the shortest path}, or {} if there is none.
std::vector<int> ShortestPathIndex(const std::vector<std::vector<Eigen::Vector2d>>& paths) {
  if (paths.empty()) return {};
  int best = 0;
  for (int i = 1; i < static_cast<int>(paths.size()); ++i) {
    if (PolylineLength(paths[i]) < PolylineLength(paths[best])) best = i;
  }
  return {best};
}

// PRM, DFS, shortcut, pruning: appends the kept paths (homotopy classes
// 0..k-1).
void RunTopologicalStages(const BaseFreeSpace& free_space, const Eigen::Vector2d& start,
                          const Eigen::Vector2d& goal, const TopologicalPathSearchOptions& o,
                          const std::stop_token& stop, TopologicalPathSearchResult* result) {
  TopologicalPathSearchStats& stats = result->stats;
  Stopwatch watch;
  VisibilityPrmGraph graph = BuildVisibilityPrm(free_space, start, goal, o.prm, stop);
  stats.num_samples = graph.num_samples;
  stats.num_guards = graph.num_guards;
  stats.num_connectors = graph.num_connectors;
  PruneDeadEnds(&graph);
  stats.prm_ms = watch.ElapsedMs();

  watch.Restart();
  const RawPathEnumeration raw = EnumerateRawPaths(graph, o.enumeration, stop);
  stats.num_raw_paths = raw.num_found;
  stats.num_kept_fewest_hops = static_cast<int>(raw.paths_W_m.size());
  stats.dfs_ms = watch.ElapsedMs();

  watch.Restart();
  const std::vector<std::vector<Eigen::Vector2d>> shortcut =
      ShortcutPaths(free_space, raw.paths_W_m, o.shortcut, stop);
  stats.num_after_shortcut = static_cast<int>(shortcut.size());
  stats.shortcut_ms = watch.ElapsedMs();

  watch.Restart();
  // Stopped: no UVD pruning (its pairwise tests would delay the return); the shortest path
  // (free, shortcut or not) is what the search had, as one class.
  const std::vector<int> kept = stop.stop_requested()
                                    ? ShortestPathIndex(shortcut)
                                    : PruneEquivalentPaths(free_space, shortcut, o.pruning);
  for (int index : kept) {
    BasePath path;
    path.waypoints_W_m = shortcut[index];
    path.length_m = PolylineLength(path.waypoints_W_m);
    path.source = BasePathSource::kTopologicalPrm;
    path.homotopy_class = static_cast<int>(result->paths.size());
    result->paths.push_back(std::move(path));
  }
  stats.num_classes_kept = static_cast<int>(kept.size());
  stats.pruning_ms = watch.ElapsedMs();
}

void RunJps(const SignedDistanceField2& field, const Eigen::Vector2d& start,
            const Eigen::Vector2d& goal, const TopologicalPathSearchOptions& o,
            const std::stop_token& stop, TopologicalPathSearchResult* result) {
  JumpPointSearchOptions jps_options = o.jps;
  jps_options.safe_distance_m = o.base_radius_m + o.clearance_m;
  const JumpPointSearchResult jps = JumpPointSearch(field, start, goal, jps_options, stop);
  result->stats.jps_ms = jps.time_s * 1e3;
  result->stats.jps_ok = jps.ok();
  if (!jps.ok()) {
    result->jps_reason = jps.reason;
    return;
  }
  BasePath path;
  path.waypoints_W_m = jps.path_W_m;
  path.length_m = jps.length_m;
  path.source = BasePathSource::kJumpPointSearch;
  path.homotopy_class = static_cast<int>(result->paths.size());
  result->paths.push_back(std::move(path));
}

}  // namespace

std::string CheckTopologicalPathSearchOptions(const TopologicalPathSearchOptions& o) {
  if (!(std::isfinite(o.base_radius_m) && o.base_radius_m >= 0.0)) {
    return "base_radius_m must be finite and >= 0";
  }
  if (!(std::isfinite(o.clearance_m) && o.clearance_m >= 0.0)) {
    return "clearance_m must be finite and >= 0";
  }
  if (!(std::isfinite(o.prm.sample_margin_length_m) && o.prm.sample_margin_length_m >= 0.0)) {
    return "prm.sample_margin_length_m must be finite and >= 0";
  }
  if (!(std::isfinite(o.prm.sample_half_width_m) && o.prm.sample_half_width_m >= 0.0)) {
    return "prm.sample_half_width_m must be finite and >= 0";
  }
  if (std::isnan(o.prm.max_time_s)) return "prm.max_time_s is NaN";
  if (!(o.pruning.max_length_ratio >= 1.0)) return "pruning.max_length_ratio must be >= 1";
  return "";
}

TopologicalPathSearchResult SearchTopologicalBasePaths(const SignedDistanceField2& field,
                                                       const Eigen::Vector2d& start_W_m,
                                                       const Eigen::Vector2d& goal_W_m,
                                                       const TopologicalPathSearchOptions& options,
                                                       std::stop_token stop) {
  const Stopwatch total;
  TopologicalPathSearchResult result;
  if (!start_W_m.allFinite() || !goal_W_m.allFinite()) {
    return Fail(std::move(result), Status::kInvalidInput,
                "start or goal base position is not finite");
  }
  if (const std::string bad = CheckTopologicalPathSearchOptions(options); !bad.empty()) {
    return Fail(std::move(result), Status::kInvalidInput, "options: " + bad);
  }
  const BaseFreeSpace free_space(field, options.base_radius_m + options.clearance_m);
  if (!free_space.IsFree(start_W_m)) {
    return Fail(std::move(result), Status::kStartInCollision,
                "start base position is outside the map or closer than base radius + "
                "clearance to an obstacle");
  }
  if (!free_space.IsFree(goal_W_m)) {
    return Fail(std::move(result), Status::kGoalInCollision,
                "goal base position is outside the map or closer than base radius + "
                "clearance to an obstacle");
  }
  if (options.mode != BasePathMode::kJpsOnly) {
    RunTopologicalStages(free_space, start_W_m, goal_W_m, options, stop, &result);
  }
  if (options.mode != BasePathMode::kTopologicalOnly && !stop.stop_requested()) {
    RunJps(field, start_W_m, goal_W_m, options, stop, &result);
  }
  result.stats.total_ms = total.ElapsedMs();
  if (!result.paths.empty()) {
    result.status = Status::kSuccess;
    return result;
  }
  if (stop.stop_requested()) return Fail(std::move(result), Status::kCancelled, "cancelled");
  std::string reason = "no base path found";
  if (!result.jps_reason.empty()) reason += " (" + result.jps_reason + ")";
  return Fail(std::move(result), Status::kNoPath, reason);
}

const char* ToString(TopologicalPathSearchResult::Status status) {
  switch (status) {
    case Status::kSuccess:
      return "success";
    case Status::kInvalidInput:
      return "invalid_input";
    case Status::kStartInCollision:
      return "start_in_collision";
    case Status::kGoalInCollision:
      return "goal_in_collision";
    case Status::kNoPath:
      return "no_path";
    case Status::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

}  // namespace topay
