#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/planning/base_free_space.h"
#include "core/planning/base_reachable_region.h"
#include "core/planning/whole_body_validity.h"

namespace topay {

/// Options of FindBaseEscape.
struct BaseEscapeOptions {
  /// Exits are searched on rings of radius step_m, 2 step_m, ... up to max_distance_m (m)
  /// around the trapped position, num_directions per ring.
  double max_distance_m = 1.0;
  double step_m = 0.02;
  int num_directions = 32;
  /// The straight move to an exit is checked every check_step_m (m), both ends included.
  double check_step_m = 0.01;
  /// When no straight move leads out: a shortest route on a lattice of this spacing (m)
  /// within max_distance_m of the trapped position, through positions the base check
  /// accepts, then shortened by straight moves (0: straight moves only).
  double route_step_m = 0.02;
};

/// A way out: waypoints from the trapped position (not included) to the exit (the last),
/// joined by straight moves that each pass the base check every check_step_m.
struct BaseEscape {
  std::vector<Eigen::Vector2d> waypoints_W_m;

  const Eigen::Vector2d& exit() const { return waypoints_W_m.back(); }
  /// Total length (m) of the moves from `from_W` through the waypoints.
  double LengthFrom(const Eigen::Vector2d& from_W) const;
};

/// Throws std::invalid_argument naming the first option out of range (distances and steps
/// finite and > 0, route_step_m finite and >= 0, at least 4 directions).
void CheckBaseEscapeOptions(const BaseEscapeOptions& options);

/// A way out for a base position the base path search cannot start from (or end at): a start
/// or goal inside an exact zone (ExactZones) that the 2D field rejects at the search's
/// clearance. Returns the nearest exit p_exit (smallest ring first; on a ring, the directions
/// closest to the base's axis first, forwards before backwards, as the base paths are driven
/// forwards and an exit behind costs a turn in place first) such that
/// free_space.IsFree(p_exit) and every checked point of the straight move p_W -> p_exit passes
/// validity.IsBaseValid (the 2D field, or in a zone the exact base cylinder): one waypoint.
/// If no straight move leads out (a base under a table top whose legs stand in the way), the
/// shortest 8-connected route on the route_step_m lattice around p_W through accepted
/// positions to a free one, shortened where a straight move passes: a few waypoints.
/// nullopt if there is neither within max_distance_m. `heading_rad`: the base's yaw.
/// The base path search then runs from the exit, and the moves are the path's first segments
/// (the arm search checks every whole-body state along them, exactly inside the zone).
/// `region`, if given: an exit must also lie in it (a base in a pocket of the field, free
/// but cut off from the other end by a table top's shadow, leaves it for the region the
/// other end's base can reach).
std::optional<BaseEscape> FindBaseEscape(const BaseFreeSpace& free_space,
                                         const WholeBodyValidity& validity,
                                         const Eigen::Vector2d& p_W, double heading_rad,
                                         const BaseEscapeOptions& options = {},
                                         const BaseReachableRegion* region = nullptr);

}  // namespace topay
