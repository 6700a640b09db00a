#include "tools/viz/robot_drawing.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "tools/viz/shapes.h"

namespace topay::viz {
namespace {

void DrawBase(WorldCanvas* canvas, const RobotModel& model, const Eigen::Isometry3d& X_WB,
              const RobotDrawingStyle& style) {
  const Eigen::Vector2d p_WB = X_WB.translation().head<2>();
  const Eigen::Vector2d x_axis_W = X_WB.linear().col(0).head<2>().normalized();
  const double yaw_rad = std::atan2(x_axis_W.y(), x_axis_W.x());
  const auto chassis = RectangleCorners(
      p_WB, Eigen::Vector2d(style.chassis_length_m, style.chassis_width_m), yaw_rad);
  const Eigen::Vector2d nose_W = p_WB + 0.5 * style.chassis_length_m * x_axis_W;
  const double arrow_px = 9.0;
  canvas->FillPolygon(chassis, colors::kWhite, style.chassis_fill_alpha);
  const double circle_px = 0.75 * style.outline_px;
  auto stroke = [&](const Rgb& colour, double extra_px) {
    canvas->DrawPolyline(chassis, /*closed=*/true, colour, style.outline_px + extra_px);
    canvas->StrokeCircle(p_WB, model.base_cylinder.radius_m, colour, circle_px + extra_px);
    canvas->DrawArrow(p_WB, nose_W, colour, style.outline_px + extra_px, arrow_px + extra_px);
  };
  // A white halo under every stroke keeps the outline visible on any map colour.
  if (style.halo) stroke(colors::kWhite, 2.0);
  stroke(style.colour, 0.0);
}

void DrawSpheres(WorldCanvas* canvas, const RobotModel& model, const KinematicsCache& cache,
                 const RobotDrawingStyle& style) {
  const std::size_t count = std::min(model.spheres.size(), cache.p_WS.size());
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return cache.p_WS[a].z() < cache.p_WS[b].z();
  });
  for (std::size_t i : order) {
    const Eigen::Vector3d& p_WS = cache.p_WS[i];
    const double radius_m = model.spheres[i].radius_m;
    canvas->FillCircle(p_WS.head<2>(), radius_m,
                       WarmRamp(style.sphere_height_m.Normalize(p_WS.z())));
    canvas->StrokeCircle(p_WS.head<2>(), radius_m, colors::kInk, 1.0);
  }
}

}  // namespace

void DrawRobot(WorldCanvas* canvas, const RobotModel& model, const KinematicsCache& cache,
               const RobotDrawingStyle& style) {
  DrawBase(canvas, model, cache.X_WB, style);
  if (style.draw_spheres) DrawSpheres(canvas, model, cache, style);
}

void DrawEndEffectorTarget(WorldCanvas* canvas, const Eigen::Isometry3d& X_WE, const Rgb& colour,
                           double radius_m) {
  const Eigen::Vector2d p_WE = X_WE.translation().head<2>();
  // cos(12 deg) = 0.978: the z axis's floor projection is then shorter than 0.21.
  Eigen::Vector2d heading = X_WE.linear().col(2).head<2>();
  if (heading.norm() < 0.21) heading = X_WE.linear().col(0).head<2>();
  canvas->StrokeCircle(p_WE, radius_m, colour, 2.5);
  const double arm = 0.7 * radius_m;
  canvas->DrawLine(p_WE - Eigen::Vector2d(arm, 0), p_WE + Eigen::Vector2d(arm, 0), colour, 2.0);
  canvas->DrawLine(p_WE - Eigen::Vector2d(0, arm), p_WE + Eigen::Vector2d(0, arm), colour, 2.0);
  if (heading.norm() > 1e-9) {
    const Eigen::Vector2d tip = p_WE + 3.0 * radius_m * heading.normalized();
    canvas->DrawArrow(p_WE + radius_m * heading.normalized(), tip, colour, 2.5, 10.0);
  }
}

}  // namespace topay::viz
