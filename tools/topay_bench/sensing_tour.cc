#include "tools/topay_bench/sensing_tour.h"

#include <algorithm>
#include <cmath>

namespace topay::bench {
namespace {

bool FootprintClear(const Scene& scene, double x_m, double y_m, const SensingTourOptions& o) {
  for (const OrientedBox& box : scene.boxes) {
    if (box.WorldBounds().min().z() >= o.pose_clear_height_m) continue;
    if (SignedDistanceToFootprint(box, Eigen::Vector2d(x_m, y_m)) < o.footprint_radius_m) return false;
  }
  return true;
}

WholeBodyState PoseWithArm(double x_m, double y_m, double yaw_rad, const WholeBodyState& arm) {
  WholeBodyState s = arm;
  s.x_m = x_m;
  s.y_m = y_m;
  s.yaw_rad = yaw_rad;
  return s;
}

void AddLine(const Scene& scene, const PlanningTask& task, const SensingTourOptions& o,
             std::vector<WholeBodyState>* states) {
  const Eigen::Vector2d from(task.start.x_m, task.start.y_m);
  const Eigen::Vector2d to(task.goal.x_m, task.goal.y_m);
  const double length_m = (to - from).norm();
  const double heading_rad = length_m > 1e-9 ? std::atan2(to.y() - from.y(), to.x() - from.x()) : task.start.yaw_rad;
  const int steps = std::max(1, static_cast<int>(std::ceil(length_m / o.line_step_m)));
  for (int k = 1; k < steps; ++k) {
    const Eigen::Vector2d p = from + (to - from) * (static_cast<double>(k) / steps);
    if (FootprintClear(scene, p.x(), p.y(), o)) states->push_back(PoseWithArm(p.x(), p.y(), heading_rad, task.start));
  }
  states->push_back(PoseWithArm(to.x(), to.y(), task.goal.yaw_rad, task.start));
}

void AddGrid(const Scene& scene, const SensingTourOptions& o, const WholeBodyState& arm,
             std::vector<WholeBodyState>* states) {
  const Eigen::Vector3d lo = scene.bounds_W_m.min(), hi = scene.bounds_W_m.max();
  const int n = std::max(1, o.grid_per_axis);
  for (int iy = 0; iy < n; ++iy) {
    for (int ix = 0; ix < n; ++ix) {
      const double fx = n == 1 ? 0.5 : static_cast<double>(ix) / (n - 1);
      const double fy = n == 1 ? 0.5 : static_cast<double>(iy) / (n - 1);
      const double x = lo.x() + o.grid_inset_m + fx * (hi.x() - lo.x() - 2.0 * o.grid_inset_m);
      const double y = lo.y() + o.grid_inset_m + fy * (hi.y() - lo.y() - 2.0 * o.grid_inset_m);
      if (FootprintClear(scene, x, y, o)) states->push_back(PoseWithArm(x, y, 0.0, arm));
    }
  }
}

}  // namespace

std::string_view SensingTourKindName(SensingTourKind kind) {
  return kind == SensingTourKind::kLine ? "line" : "tour";
}

std::optional<SensingTourKind> ParseSensingTourKind(std::string_view name) {
  if (name == "line") return SensingTourKind::kLine;
  if (name == "tour") return SensingTourKind::kTour;
  return std::nullopt;
}

std::vector<WholeBodyState> SensingTourStates(const Scene& scene, const PlanningTask& task,
                                              const SensingTourOptions& options) {
  std::vector<WholeBodyState> states{task.start};
  AddLine(scene, task, options, &states);
  if (options.kind == SensingTourKind::kTour) AddGrid(scene, options, task.start, &states);
  return states;
}

}  // namespace topay::bench
