#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/robot/kinematics.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "tools/viz/color.h"
#include "tools/viz/color_map.h"
#include "tools/viz/world_canvas.h"

namespace topay::viz {

/// How DrawTrajectory shows a whole-body trajectory from above.
struct TrajectoryDrawingStyle {
  Rgb path_colour{20, 20, 20};
  double path_width_px = 2.5;
  bool path_halo = true;  ///< White line under the path, for contrast on the map.
  double path_sample_period_s = 0.01;
  /// Footprints (chassis rectangle 0.685 x 0.57 m, base cylinder circle, heading arrow) and
  /// arm silhouettes (every collision sphere projected, filled by height) at 0 < t < end,
  /// every footprint_interval_s (FootprintTimes). The start and end poses are drawn by the
  /// caller in their own colours.
  double footprint_interval_s = 1.0;
  /// Footprint outlines go from early_colour (t = 0) to late_colour (t = end).
  Rgb early_colour = colors::kStart;
  Rgb late_colour = colors::kGoal;
  double footprint_outline_px = 1.5;
  double chassis_fill_alpha = 0.3;
  bool draw_arm = true;
  ScalarRange sphere_height_m{0.0, 1.6};
};

/// The footprint times strictly inside (0, duration): interval, 2 interval, ... (a time
/// within interval / 4 of the end is dropped, so the last footprint does not sit on the end
/// pose). Throws std::invalid_argument for an interval that is not finite and >= 0.05 s or a
/// duration that is not finite and >= 0.
std::vector<double> FootprintTimes(double duration_s, double interval_s);

/// The base position (x, y) at t = 0, period, ... and at the exact end.
std::vector<Eigen::Vector2d> SampleBasePath(const ArcYawTrajectory& trajectory, double period_s);

/// The footprint outline colour at time t_s of a trajectory of duration_s.
Rgb FootprintColour(const TrajectoryDrawingStyle& style, double t_s, double duration_s);

/// Draws the base path (with a halo), then the footprints and arm silhouettes at
/// FootprintTimes, each outlined in FootprintColour. `kinematics` must be the trajectory's
/// robot. Throws std::invalid_argument for a trajectory of another joint count, an unsolved
/// one, or a bad style (period or interval).
void DrawTrajectory(WorldCanvas* canvas, const ArcYawTrajectory& trajectory,
                    const Kinematics& kinematics, const TrajectoryDrawingStyle& style = {});

}  // namespace topay::viz
