#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <stop_token>
#include <string>
#include <vector>

#include "core/map/signed_distance_field2.h"
#include "core/planning/path_shortcut.h"

namespace topay {

/// Options of JumpPointSearch.
struct JumpPointSearchOptions {
  /// A cell is traversable when its field value is >= this (base radius 0.40 +
  /// 0.1 m) plus 1e-6 m (a guard against rounding in the interpolation between
  /// traversable cells).
  double safe_distance_m = 0.5;
  /// Shortcut the cell path against the field (at safe_distance_m) before
  /// returning it.
  bool shortcut = true;
  PathShortcutOptions shortcut_options;
  /// Safety cap on expanded jump points.
  std::int64_t max_expansions = 10'000'000;
};

/// Outcome of JumpPointSearch.
struct JumpPointSearchResult {
  enum class Status {
    kSuccess,
    kInvalidInput,  ///< NaN/inf position or bad options.
    kStartBlocked,  ///< Start outside the map, not free, or sees no traversable
                    ///< cell.
    kGoalBlocked,   ///< Same for the goal.
    kNoPath,        ///< Start and goal cells are not connected.
    kExpansionCapHit,
    kCancelled,
  };
  Status status = Status::kInvalidInput;
  std::string reason;  ///< Human-readable failure reason (empty on success).
  /// Start position, traversable cell centres at the jump points (or the
  /// shortcut vertices), goal position. Every segment is free at
  /// safe_distance_m. Empty on failure.
  std::vector<Eigen::Vector2d> path_W_m;
  double length_m = 0.0;
  double grid_length_m = 0.0;  ///< Length of the cell-centre path before the shortcut.
  std::int64_t num_expanded = 0;
  double time_s = 0.0;

  bool ok() const { return status == Status::kSuccess; }
};

/// Jump Point Search (Harabor and Grastien 2011) on the field's grid,
/// 8-connected, in the variant where a diagonal step needs both adjacent
/// orthogonal cells traversable (no corner cutting); octile heuristic, optimal
/// on the grid. Start and goal are connected to the grid through the nearest
/// traversable cell centre (among their cell and its 8 neighbours) they see in
/// the field. The stop token is polled at the first expansion and every 256
/// after.
JumpPointSearchResult JumpPointSearch(const SignedDistanceField2& field,
                                      const Eigen::Vector2d& start_W_m,
                                      const Eigen::Vector2d& goal_W_m,
                                      const JumpPointSearchOptions& options = {},
                                      std::stop_token stop = {});

}  // namespace topay
