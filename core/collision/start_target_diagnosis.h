#pragma once

#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Exact-geometry explanations of why a start state or a target cannot be planned for, in
/// words a user can act on: which joint, which box, which body. They use the scene's boxes and
/// the robot model directly (no distance field), so they can run before any map is built and
/// name the cause where a field-based check only says "collision".

struct StartDiagnosisOptions {
  /// A base or arm sphere at most this far (m) from a box is reported (0: touching or
  /// penetrating).
  double obstacle_margin_m = 0.0;
  /// A self-collision pair or the arm above the chassis at most this far (m) is reported.
  double self_margin_m = 0.0;
};

/// The first problem of `state` in this order, or nullopt if there is none:
///  - malformed: wrong joint count or a non-finite value;
///  - a joint outside its position limits: "joint 'joint3' (q3) is 3.300 rad, outside its
///    limits [-3.100, 3.100] rad";
///  - the base position outside the scene bounds (x, y);
///  - the base cylinder within the obstacle margin of a box: "the base (cylinder radius
///    0.400 m) penetrates box 12 (centre (1.000, 2.000, 0.400) m, size ...) by 0.052 m";
///  - an arm sphere within the margin of a box, naming the sphere, its link and the box;
///  - a self-collision pair (both spheres and links) or a sphere below the chassis top.
/// Each box is named by its index in Scene::boxes. Obstacle distances are exact
/// (core/collision/scene_clearance.h).
std::optional<std::string> DiagnoseStartState(const Kinematics& kinematics, const Scene& scene,
                                              const WholeBodyState& state,
                                              const StartDiagnosisOptions& options = {});

/// The first problem of an end-effector target X_WE, or nullopt: not finite, a rotation that
/// is not orthonormal, the point p_WE below the floor (z below the scene bounds' minimum z),
/// outside the room (the scene bounds), or inside a box ("inside box 7 (centre ..., size ...),
/// 0.120 m deep", and how many other boxes hold it).
std::optional<std::string> DiagnoseTarget(const Scene& scene, const Eigen::Isometry3d& X_WE);

}  // namespace topay
