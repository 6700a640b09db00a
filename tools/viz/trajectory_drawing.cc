#include "tools/viz/trajectory_drawing.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "tools/viz/robot_drawing.h"

namespace topay::viz {
namespace {

void CheckTrajectory(const ArcYawTrajectory& trajectory, const Kinematics& kinematics) {
  if (!trajectory.minco().solved()) {
    throw std::invalid_argument("DrawTrajectory: the trajectory has not been solved");
  }
  if (trajectory.num_joints() != kinematics.num_joints()) {
    throw std::invalid_argument("DrawTrajectory: the trajectory has " +
                                std::to_string(trajectory.num_joints()) + " joints, the robot " +
                                std::to_string(kinematics.num_joints()));
  }
}

void DrawPath(WorldCanvas* canvas, const std::vector<Eigen::Vector2d>& path_W,
              const TrajectoryDrawingStyle& style) {
  if (style.path_halo) {
    canvas->DrawPolyline(path_W, /*closed=*/false, colors::kWhite, style.path_width_px + 2.5);
  }
  canvas->DrawPolyline(path_W, /*closed=*/false, style.path_colour, style.path_width_px);
}

}  // namespace

std::vector<double> FootprintTimes(double duration_s, double interval_s) {
  if (!(std::isfinite(interval_s) && interval_s >= 0.05)) {
    throw std::invalid_argument("FootprintTimes: interval " + std::to_string(interval_s) +
                                " s is not finite and >= 0.05 s");
  }
  if (!(std::isfinite(duration_s) && duration_s >= 0.0)) {
    throw std::invalid_argument("FootprintTimes: duration " + std::to_string(duration_s) +
                                " s is not finite and >= 0");
  }
  std::vector<double> times;
  for (long k = 1;; ++k) {
    const double t_s = static_cast<double>(k) * interval_s;
    if (t_s > duration_s - 0.25 * interval_s) break;
    times.push_back(t_s);
  }
  return times;
}

std::vector<Eigen::Vector2d> SampleBasePath(const ArcYawTrajectory& trajectory, double period_s) {
  if (!(period_s >= 1e-4 && period_s <= 10.0)) {
    throw std::invalid_argument("SampleBasePath: period " + std::to_string(period_s) +
                                " s is outside [1e-4, 10] s");
  }
  TrajectorySample point = trajectory.MakePoint();
  std::vector<Eigen::Vector2d> path;
  const double end_s = trajectory.duration_s();
  for (long k = 0;; ++k) {
    const double t_s = static_cast<double>(k) * period_s;
    if (t_s >= end_s - 1e-9) break;
    trajectory.Evaluate(t_s, &point);
    path.emplace_back(point.state.x_m, point.state.y_m);
  }
  trajectory.Evaluate(end_s, &point);
  path.emplace_back(point.state.x_m, point.state.y_m);
  return path;
}

Rgb FootprintColour(const TrajectoryDrawingStyle& style, double t_s, double duration_s) {
  const double fraction = duration_s > 0.0 ? t_s / duration_s : 0.0;
  return Lerp(style.early_colour, style.late_colour, fraction);
}

void DrawTrajectory(WorldCanvas* canvas, const ArcYawTrajectory& trajectory,
                    const Kinematics& kinematics, const TrajectoryDrawingStyle& style) {
  CheckTrajectory(trajectory, kinematics);
  const double duration_s = trajectory.duration_s();
  const std::vector<double> times = FootprintTimes(duration_s, style.footprint_interval_s);
  DrawPath(canvas, SampleBasePath(trajectory, style.path_sample_period_s), style);

  KinematicsCache cache = kinematics.MakeCache();
  TrajectorySample point = trajectory.MakePoint();
  RobotDrawingStyle robot;
  robot.outline_px = style.footprint_outline_px;
  robot.chassis_fill_alpha = style.chassis_fill_alpha;
  robot.halo = false;
  robot.draw_spheres = style.draw_arm;
  robot.sphere_height_m = style.sphere_height_m;
  for (double t_s : times) {
    trajectory.Evaluate(t_s, &point);
    kinematics.Update(point.state, &cache);
    robot.colour = FootprintColour(style, t_s, duration_s);
    DrawRobot(canvas, kinematics.model(), cache, robot);
  }
}

}  // namespace topay::viz
