#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/map/signed_distance_field2.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "tools/viz/box_drawing.h"
#include "tools/viz/field_drawing.h"
#include "tools/viz/image.h"
#include "tools/viz/legend.h"
#include "tools/viz/map_axes.h"
#include "tools/viz/robot_drawing.h"
#include "tools/viz/world_canvas.h"

namespace topay::viz {

/// One robot configuration to draw over the scene, e.g. a task's start or goal.
struct RobotPoseDrawing {
  WholeBodyState state;
  Rgb colour = colors::kStart;
  std::string label;  ///< Legend entry ("start", "goal"); empty: none.
};

/// An end-effector target pose to mark.
struct TargetDrawing {
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  Rgb colour = colors::kTarget;
  std::string label;
};

/// Everything a top-down scene drawing shows. Only `scene` is required; pointers must outlive
/// the RenderScene call.
struct SceneDrawing {
  const Scene* scene = nullptr;
  const SignedDistanceField2* base_field = nullptr;  ///< Colour map underneath, if given.
  const Kinematics* kinematics = nullptr;            ///< Required if `robots` is not empty.
  std::vector<RobotPoseDrawing> robots;
  std::vector<TargetDrawing> targets;
  /// Legend text before the keys, e.g. {"tables seed 7, 301 boxes", "medium task ..."}: each
  /// on the first row if they fit, else wrapped between entries.
  std::vector<std::string> title_lines;
};

struct SceneRenderOptions {
  double px_per_m = 40.0;       ///< Scale of the map.
  double margin_m = 0.25;       ///< Paper around the scene's bounds, inside the axes.
  double font_px = 13.0;        ///< Legend text height.
  MapAxesStyle axes;            ///< Metric axes around the map.
  double right_px = 16.0;       ///< Paper right of the map.
  double top_px = 12.0;         ///< Paper above the map.
  FieldDrawingOptions field;    ///< Distance colour map (default: the field's min..max).
  BoxDrawingOptions boxes;      ///< top_height_m is overwritten by the scene's z range.
  RobotDrawingStyle robot;      ///< colour is overwritten per pose.
};

/// What a drawing contains beyond the scene itself (the trajectory view's layer).
struct SceneOverlay {
  std::function<void(WorldCanvas*)> draw;     ///< Over the map, after everything else.
  std::function<void(LegendLayout*)> legend;  ///< More legend keys, on a row of their own.
};

/// Where things went in a drawing, for callers and tests.
struct SceneRenderReport {
  LegendBox map_px;                          ///< The map block (inside the axes' frame).
  std::optional<ScalarRange> field_range_m;  ///< The clearance colour scale, if a field.
  std::optional<LegendBox> clearance_bar;    ///< Its colour bar: min at x0, max at x1.
};

/// The map view of RenderScene for this scene and options: the scene's xy bounds plus
/// margin_m at px_per_m, its top-left corner right of the y axis and below top_px.
ViewTransform SceneMapView(const Scene& scene, const SceneRenderOptions& options = {});

/// Width of RenderScene's image for a map block `map_width_px` wide: the y axis's room, the
/// map and right_px.
int SceneImageWidth(int map_width_px, const SceneRenderOptions& options = {});

/// Draws the scene from above: the 2D base distance field as a colour map spanning the values
/// the field holds, every box's footprint shaded by its top height (raised boxes hatched),
/// each robot pose (chassis, base cylinder, arm spheres by height), each end-effector target,
/// then `overlay.draw`; metric axes (ticks and coordinates in metres) around the map; below
/// them a legend (title, pose colours, colour bars for heights and clearance with their end
/// values, a scale bar, then overlay.legend's keys). Throws std::invalid_argument for a null
/// scene, robots without kinematics, a state of the wrong size or with NaN, or options that
/// make an impossible image.
Image RenderScene(const SceneDrawing& drawing, const SceneRenderOptions& options = {},
                  SceneRenderReport* report = nullptr, const SceneOverlay& overlay = {});

}  // namespace topay::viz
