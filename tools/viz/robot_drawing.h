#pragma once

#include <Eigen/Geometry>

#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "tools/viz/color.h"
#include "tools/viz/color_map.h"
#include "tools/viz/world_canvas.h"

namespace topay::viz {

/// How DrawRobot shows one whole-body configuration from above.
struct RobotDrawingStyle {
  Rgb colour = colors::kStart;  ///< Outline of chassis and base cylinder, heading arrow.
  /// Chassis footprint (m), centred on the base frame, x forward. The RobotModel carries only
  /// the collision cylinder; these defaults are the paper's platform (0.685 x 0.57 m, the
  /// URDF's chassis box).
  double chassis_length_m = 0.685;
  double chassis_width_m = 0.57;
  double chassis_fill_alpha = 0.55;  ///< White chassis fill over the map.
  double outline_px = 2.0;
  bool halo = true;  ///< White outline under the coloured strokes, for contrast.
  /// Sphere centre heights (m) mapped onto the warm ramp (pale low, dark red high).
  ScalarRange sphere_height_m{0.0, 1.6};
  bool draw_spheres = true;
};

/// Draws the robot at the configuration last computed into `cache` (Kinematics::Update):
/// the chassis rectangle and the base collision cylinder's circle, both oriented by the base
/// yaw, a heading arrow along the base x axis, and every arm collision sphere projected to a
/// circle of its radius, filled by the height of its centre and drawn low to high.
void DrawRobot(WorldCanvas* canvas, const RobotModel& model, const KinematicsCache& cache,
               const RobotDrawingStyle& style = {});

/// Draws an end-effector target pose X_WE: a ring with a cross at the origin of E and an arrow
/// for its heading. The heading is E's z axis (the tool's approach direction) projected on the
/// floor; when that axis is within ~12 deg of vertical, E's x axis is used instead.
void DrawEndEffectorTarget(WorldCanvas* canvas, const Eigen::Isometry3d& X_WE, const Rgb& colour,
                           double radius_m = 0.15);

}  // namespace topay::viz
