#include "sim/scenarios/route_box.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/geometry/box_overlap.h"
#include "sim/scenarios/sensed_reachability.h"

namespace topay {
namespace {

void Require(bool ok, const char* option, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("route box option ") + option + ": " + what);
}

bool OverlapsScene(const OrientedBox& box, double gap_m, const Scene& scene) {
  OrientedBox grown = box;
  grown.size_m += Eigen::Vector3d(gap_m, gap_m, gap_m);
  return std::any_of(scene.boxes.begin(), scene.boxes.end(),
                     [&](const OrientedBox& b) { return BoxesOverlap(grown, b); });
}

bool GoalStaysReachable(const RouteQuery& route, const OrientedBox& box, const Scene& scene,
                        const Kinematics& kinematics) {
  Scene with_box = scene;
  with_box.boxes.push_back(box);
  return SensedReachableRegion(with_box, kinematics, route.p_WR_m).Reaches(route.path_W_m.back());
}

double ArcLength(const std::vector<Eigen::Vector2d>& path, std::size_t from, std::size_t to) {
  double s = 0.0;
  for (std::size_t i = from; i < to; ++i) s += (path[i + 1] - path[i]).norm();
  return s;
}

}  // namespace

void CheckRouteBoxOptions(const RouteBoxOptions& o) {
  Require(std::isfinite(o.ahead_min_m) && o.ahead_min_m > 0.0, "ahead_min_m", "must be finite and > 0");
  Require(std::isfinite(o.ahead_max_m) && o.ahead_max_m >= o.ahead_min_m, "ahead_max_m", "must be finite and >= ahead_min_m");
  Require(std::isfinite(o.side_min_m) && o.side_min_m > 0.0, "side_min_m", "must be finite and > 0");
  Require(std::isfinite(o.side_max_m) && o.side_max_m >= o.side_min_m, "side_max_m", "must be finite and >= side_min_m");
  Require(std::isfinite(o.height_m) && o.height_m > 0.0, "height_m", "must be finite and > 0");
  Require(std::isfinite(o.min_robot_distance_m) && o.min_robot_distance_m >= 0.0, "min_robot_distance_m",
          "must be finite and >= 0");
  Require(std::isfinite(o.scene_gap_m) && o.scene_gap_m >= 0.0, "scene_gap_m", "must be finite and >= 0");
  Require(std::isfinite(o.end_margin_m) && o.end_margin_m >= 0.0, "end_margin_m", "must be finite and >= 0");
  Require(o.tries >= 1, "tries", "must be >= 1");
}

std::size_t IndexAtArcLength(const std::vector<Eigen::Vector2d>& path, std::size_t from, double s_m) {
  double s = 0.0;
  for (std::size_t i = from + 1; i < path.size(); ++i) {
    s += (path[i] - path[i - 1]).norm();
    if (s >= s_m) return i;
  }
  return path.size();
}

std::optional<RouteBox> PlaceRouteBox(const RouteQuery& route, const Scene& scene, const Kinematics& kinematics,
                                      const RouteBoxOptions& options, Rng* rng) {
  CheckRouteBoxOptions(options);
  if (route.path_W_m.empty() || route.robot_index >= route.path_W_m.size()) return std::nullopt;
  for (int k = 0; k < options.tries; ++k) {
    const double ahead_m = rng->Uniform(options.ahead_min_m, options.ahead_max_m);
    const double side_m = rng->Uniform(options.side_min_m, options.side_max_m);
    const std::size_t at = IndexAtArcLength(route.path_W_m, route.robot_index, ahead_m);
    if (at >= route.path_W_m.size() ||
        IndexAtArcLength(route.path_W_m, at, options.end_margin_m) >= route.path_W_m.size()) {
      continue;  // too near the end: the box would stand on the goal
    }
    RouteBox placed;
    placed.path_index = at;
    placed.box.center_W_m = Eigen::Vector3d(route.path_W_m[at].x(), route.path_W_m[at].y(), 0.5 * options.height_m);
    placed.box.size_m = Eigen::Vector3d(side_m, side_m, options.height_m);
    placed.box.yaw_rad = 0.0;
    if ((route.path_W_m[at] - route.p_WR_m).norm() < options.min_robot_distance_m) continue;
    if (OverlapsScene(placed.box, options.scene_gap_m, scene)) continue;
    if (!GoalStaysReachable(route, placed.box, scene, kinematics)) continue;
    placed.ahead_m = ArcLength(route.path_W_m, route.robot_index, at);
    return placed;
  }
  return std::nullopt;
}

std::optional<RouteBox> RecheckRouteBox(const RouteBox& placed, const RouteQuery& now, const RouteBoxOptions& options) {
  const std::vector<Eigen::Vector2d>& path = now.path_W_m;
  if (placed.path_index >= path.size() || now.robot_index > placed.path_index) return std::nullopt;
  if ((placed.box.center_W_m.head<2>() - now.p_WR_m).norm() < options.min_robot_distance_m) return std::nullopt;
  std::size_t nearest = now.robot_index;
  for (std::size_t i = now.robot_index; i <= placed.path_index; ++i) {
    if ((path[i] - now.p_WR_m).norm() < (path[nearest] - now.p_WR_m).norm()) nearest = i;
  }
  if (nearest >= placed.path_index) return std::nullopt;
  RouteBox out = placed;
  out.ahead_m = ArcLength(path, nearest, placed.path_index);
  return out;
}

}  // namespace topay
