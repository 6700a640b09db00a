#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/geometry/scene.h"
#include "core/map/signed_distance_field2.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "tools/viz/image.h"
#include "tools/viz/scene_renderer.h"
#include "tools/viz/trajectory_drawing.h"
#include "tools/viz/view_transform.h"

namespace topay::viz {

/// A planned (or failed) query seen from above. Pointers must outlive the call.
struct TrajectoryView {
  const Scene* scene = nullptr;                      ///< Required.
  const SignedDistanceField2* base_field = nullptr;  ///< Colour map underneath, if given.
  const Kinematics* kinematics = nullptr;            ///< Required.
  WholeBodyState start;
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();
  /// The trajectory; null when the plan failed (then only the start and the target show).
  const ArcYawTrajectory* trajectory = nullptr;
  std::vector<std::string> title_lines;  ///< Legend text, as SceneDrawing::title_lines.
};

struct TrajectoryViewOptions {
  SceneRenderOptions scene;           ///< Scale, margins, legend text size, colours.
  TrajectoryDrawingStyle trajectory;  ///< Path, footprints, arm silhouettes.
};

/// The scene exactly as RenderScene draws it (distance field, boxes, the end-effector target
/// and its legend, metric axes), then over the map: the trajectory (DrawTrajectory: base path,
/// footprints and arm silhouettes at regular times), the start pose (blue) and the end pose
/// (vermilion) with their arms, and the target again on top; after RenderScene's legend a row
/// with the keys of the trajectory layer (start, end, base path, footprint time, arm height).
/// Throws std::invalid_argument for a missing scene or kinematics, a start state of the
/// wrong size or not finite, or what RenderScene and DrawTrajectory reject.
Image RenderTrajectoryView(const TrajectoryView& view, const TrajectoryViewOptions& options = {},
                           SceneRenderReport* report = nullptr);

}  // namespace topay::viz
