#pragma once

#include <Eigen/Core>
#include <stop_token>
#include <string>
#include <vector>

#include "core/map/signed_distance_field2.h"
#include "core/planning/base_path.h"
#include "core/planning/jump_point_search.h"
#include "core/planning/path_shortcut.h"
#include "core/planning/topological_path_enumeration.h"
#include "core/planning/uvd_equivalence.h"
#include "core/planning/visibility_prm.h"

namespace topay {

/// Which base-path generators run (paper Sec. III-A and its Table I ablation).
enum class BasePathMode {
  kTopologicalWithJps,  ///< Topological PRM paths plus one JPS path (TopAY).
  kTopologicalOnly,     ///< Topological PRM paths only.
  kJpsOnly,             ///< The "JPS only" ablation: one JPS path.
};

/// Options of SearchTopologicalBasePaths; defaults are the authors' code's
/// front-end figures.
struct TopologicalPathSearchOptions {
  BasePathMode mode = BasePathMode::kTopologicalWithJps;
  /// Base collision radius (m): set it from RobotModel::base_cylinder.radius_m.
  double base_radius_m = 0.40;
  /// Extra clearance (m): a base position is free when field >= base_radius_m +
  /// clearance_m; the JPS safe distance is the same sum.
  double clearance_m = 0.1;
  VisibilityPrmOptions prm;
  RawPathEnumerationOptions enumeration;  ///< DFS: 300 raw paths, keep 25 fewest hops.
  PathShortcutOptions shortcut;
  UvdPruningOptions pruning;   ///< Keep <= 6 paths, <= 2.0 x the shortest.
  JumpPointSearchOptions jps;  ///< safe_distance_m is overwritten by the sum above.
};

/// Empty if the options are usable, else the first option out of range and its rule (Search
/// returns kInvalidInput with it; the planner YAML loader throws it as a ConfigError).
std::string CheckTopologicalPathSearchOptions(const TopologicalPathSearchOptions& options);

/// Counters and wall-clock timings (steady clock, ms) of one search.
struct TopologicalPathSearchStats {
  int num_samples = 0;
  int num_guards = 0;
  int num_connectors = 0;
  int num_raw_paths = 0;         ///< Found by the DFS.
  int num_kept_fewest_hops = 0;  ///< Passed to the shortcut.
  int num_after_shortcut = 0;
  int num_classes_kept = 0;  ///< Topological PRM paths returned (JPS not counted).
  bool jps_ok = false;
  double prm_ms = 0.0;
  double dfs_ms = 0.0;
  double shortcut_ms = 0.0;
  double pruning_ms = 0.0;
  double jps_ms = 0.0;
  double total_ms = 0.0;
};

/// Output of SearchTopologicalBasePaths.
struct TopologicalPathSearchResult {
  enum class Status {
    kSuccess,           ///< At least one path.
    kInvalidInput,      ///< NaN/inf positions or bad options.
    kStartInCollision,  ///< Start outside the map or closer than base radius +
                        ///< clearance.
    kGoalInCollision,
    kNoPath,     ///< No generator found a path.
    kCancelled,  ///< The stop token fired before any path was found.
  };
  Status status = Status::kInvalidInput;
  std::string reason;  ///< Empty on success; names what failed otherwise.
  /// Topological PRM paths by increasing length (homotopy_class 0, 1, ...),
  /// then the JPS path (homotopy_class = next free index). Every segment is
  /// free at base radius + clearance.
  std::vector<BasePath> paths;
  TopologicalPathSearchStats stats;
  std::string jps_reason;  ///< JPS failure reason when JPS ran and failed (not fatal).

  bool ok() const { return status == Status::kSuccess; }
};

/// The front end's base-path stage (paper Sec. III-A): visibility PRM in the
/// start-goal box, DFS enumeration of raw paths, parallel shortcutting, UVD
/// pruning, sorting and filtering by length, and the extra JPS candidate, as
/// selected by options.mode. Never throws for bad positions (status + reason
/// instead); the stop token is polled in every stage's loop (shortcutting
/// included), and a cancelled search returns what it had (status kCancelled if
/// nothing): when stopped before the UVD pruning, the pruning is skipped and the
/// shortest raw/partly shortcut path is returned as the only class.
TopologicalPathSearchResult SearchTopologicalBasePaths(
    const SignedDistanceField2& field, const Eigen::Vector2d& start_W_m,
    const Eigen::Vector2d& goal_W_m, const TopologicalPathSearchOptions& options = {},
    std::stop_token stop = {});

/// Short English name of a status, e.g. "start_in_collision".
const char* ToString(TopologicalPathSearchResult::Status status);

}  // namespace topay
