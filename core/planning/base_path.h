#pragma once

#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace topay {

/// Where a base path came from. kStanding: the base stays where it stands (a goal candidate
/// found with the arm alone, GoalCandidate::base_stays; no search): start and goal coincide.
enum class BasePathSource { kTopologicalPrm, kJumpPointSearch, kStanding };

/// "topological_prm", "jps", "standing" (PLANNER_PATHS' source).
std::string_view BasePathSourceName(BasePathSource source);

/// A collision-free polyline for the base in the world's xy plane (paper Sec. III-A: one
/// element of P_b), from the start base position to the goal base position.
struct BasePath {
  std::vector<Eigen::Vector2d> waypoints_W_m;  ///< First = start, last = goal; >= 2 points.
  double length_m = 0.0;
  BasePathSource source = BasePathSource::kTopologicalPrm;
  /// Index of the homotopy class among the paths returned by one search (0 = shortest); JPS
  /// paths get the next free index whether or not they share a class with a PRM path.
  int homotopy_class = 0;
};

/// Length of a polyline (m).
double PolylineLength(const std::vector<Eigen::Vector2d>& waypoints_W_m);

}  // namespace topay
