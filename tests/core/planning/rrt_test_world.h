#pragma once

// Shared by the whole-body validity and arm RRT* tests: the robot, a hand-made scene with its
// distance fields, and an exact (scene-box) check of whole-body paths that does not use the
// planner's own interpolation code.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/collision/scene_clearance.h"
#include "core/geometry/scene.h"
#include "core/map/scene_distance_fields.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay::testing {

/// A robot in a scene: model, kinematics, distance fields and the exact checker.
struct RrtTestWorld {
  explicit RrtTestWorld(Scene scene_in)
      : model(LoadTopayModel()),
        kinematics(model),
        scene(std::move(scene_in)),
        fields(BuildSceneDistanceFields(scene)),
        exact(kinematics, scene) {}

  RobotModel model;
  Kinematics kinematics;
  Scene scene;
  SceneDistanceFields fields;
  SceneClearanceChecker exact;
};

/// Exact check of a whole-body path: every state and every edge, linearly interpolated in
/// (x, y, yaw, q) so that consecutive checked states differ by at most 1 cm in base position
/// and 0.01 rad in yaw and each joint, must be collision free against the scene's boxes
/// (SceneClearance::IsCollisionFree(0, 0)) and within the joint limits. Returns an empty
/// string or a description of the first failure.
inline std::string ExactPathFailure(const RrtTestWorld& world,
                                    const std::vector<WholeBodyState>& states) {
  SceneClearanceWorkspace workspace = world.exact.MakeWorkspace();
  const JointLimits& limits = world.model.joint_limits;
  auto check = [&](const WholeBodyState& s) -> std::string {
    if (((s.q_rad - limits.q_min_rad).array() < 0.0).any() ||
        ((limits.q_max_rad - s.q_rad).array() < 0.0).any()) {
      return "joint limit";
    }
    if (!world.exact.IsCollisionFree(s, 0.0, 0.0, &workspace)) return "exact collision";
    return {};
  };
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (std::string failure = check(states[k]); !failure.empty()) {
      return failure + " at state " + std::to_string(k);
    }
    if (k == 0) continue;
    const WholeBodyState& a = states[k - 1];
    const WholeBodyState& b = states[k];
    const double largest = std::max({std::hypot(b.x_m - a.x_m, b.y_m - a.y_m) / 0.01,
                                     std::abs(b.yaw_rad - a.yaw_rad) / 0.01,
                                     (b.q_rad - a.q_rad).cwiseAbs().maxCoeff() / 0.01});
    const int n = std::max(1, static_cast<int>(std::ceil(largest)));
    for (int i = 1; i < n; ++i) {
      const double s = static_cast<double>(i) / n;
      WholeBodyState mid;
      mid.x_m = a.x_m + s * (b.x_m - a.x_m);
      mid.y_m = a.y_m + s * (b.y_m - a.y_m);
      mid.yaw_rad = a.yaw_rad + s * (b.yaw_rad - a.yaw_rad);
      mid.q_rad = a.q_rad + s * (b.q_rad - a.q_rad);
      if (std::string failure = check(mid); !failure.empty()) {
        return failure + " on edge " + std::to_string(k - 1) + " -> " + std::to_string(k);
      }
    }
  }
  return {};
}

}  // namespace topay::testing
