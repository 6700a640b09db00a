#pragma once
// A box put on the robot's route a few metres ahead of it, for scripted disturbances
// (topay-director's box_on_route event, docs/director.md): the geometry only, free of the bus.

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/common/random.h"
#include "core/geometry/oriented_box.h"
#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"

namespace topay {

struct RouteBoxOptions {
  /// Arc length (m) along the path from the robot to the box's centre, uniform in [min, max].
  double ahead_min_m = 2.5;
  double ahead_max_m = 3.5;
  /// The box's square footprint side (m), uniform in [min, max], and its height (m); it stands
  /// on the floor, yaw 0.
  double side_min_m = 0.4;
  double side_max_m = 0.6;
  double height_m = 1.0;
  /// The box's centre stays at least this far (m, xy) from the robot's base, also at the
  /// re-check just before it goes out.
  double min_robot_distance_m = 2.0;
  /// The box grown by this (m, each side length) overlaps no box of the scene.
  double scene_gap_m = 0.3;
  /// At least this much path (m) is left beyond the box (not on the goal itself).
  double end_margin_m = 1.0;
  /// Draws of (ahead, side) per placement.
  int tries = 20;
};

/// Throws std::invalid_argument naming the first option out of range (ranges min <= max,
/// lengths > 0 or >= 0 as documented, tries >= 1).
void CheckRouteBoxOptions(const RouteBoxOptions& options);

/// The robot on its route: the active trajectory's base positions in time order (a few cm
/// apart), the sample it is at by time, and its measured base position.
struct RouteQuery {
  std::vector<Eigen::Vector2d> path_W_m;
  std::size_t robot_index = 0;
  Eigen::Vector2d p_WR_m = Eigen::Vector2d::Zero();
};

struct RouteBox {
  OrientedBox box;
  std::size_t path_index = 0;  ///< The path sample the box is centred on.
  double ahead_m = 0.0;        ///< Arc length from the robot (its nearest sample) to the box.
};

/// The first sample at least s_m of arc length after `from`; path.size() if none.
std::size_t IndexAtArcLength(const std::vector<Eigen::Vector2d>& path, std::size_t from, double s_m);

/// Up to options.tries draws (ahead_m, then the side, from `rng`), each rejected if: the path
/// ends within end_margin_m beyond the box, the box's centre is nearer than
/// min_robot_distance_m to the robot, the box grown by scene_gap_m overlaps a box of `scene`,
/// or with the box added the path's last sample (the goal's base) is not in
/// SensedReachableRegion from the robot. The first draw kept; nullopt if none (or an empty
/// path). `kinematics` must be the robot's.
std::optional<RouteBox> PlaceRouteBox(const RouteQuery& route, const Scene& scene, const Kinematics& kinematics,
                                      const RouteBoxOptions& options, Rng* rng);

/// The re-check just before the box goes out (the checks take time; the robot moves on): the
/// box again at least min_robot_distance_m from the robot's base in `now` and still ahead of
/// it (the robot's nearest sample from now.robot_index up to the box's comes before it);
/// `placed` with ahead_m measured from there, else nullopt.
std::optional<RouteBox> RecheckRouteBox(const RouteBox& placed, const RouteQuery& now, const RouteBoxOptions& options);

}  // namespace topay
