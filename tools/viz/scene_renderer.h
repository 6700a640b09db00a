#pragma once

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
#include "tools/viz/robot_drawing.h"

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
  double margin_m = 0.25;       ///< Paper around the scene's bounds.
  int text_scale = 2;           ///< Bitmap-font pixel size of the legend.
  FieldDrawingOptions field;    ///< Distance colour map: 0..clip_m (default 2 m).
  BoxDrawingOptions boxes;      ///< top_height_m is overwritten by the scene's z range.
  RobotDrawingStyle robot;      ///< colour is overwritten per pose.
};

/// Draws the scene from above: the 2D base distance field as a colour map, every box's
/// footprint shaded by its top height (raised boxes hatched), each robot pose (chassis, base
/// cylinder, arm spheres by height), each end-effector target, then below the map a legend
/// (title, pose colours, colour bars for heights and distances) and a scale bar in metres.
/// The map covers the scene's bounds_W_m in xy plus the margin.
/// Throws std::invalid_argument for a null scene, robots without kinematics, a state of the
/// wrong size or with NaN, or options that make an impossible image.
Image RenderScene(const SceneDrawing& drawing, const SceneRenderOptions& options = {});

}  // namespace topay::viz
