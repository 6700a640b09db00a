#pragma once

#include <cstdint>
#include <optional>

#include <Eigen/Geometry>

#include "core/robot/whole_body_state.h"
#include "sim/scenes/distance_range.h"
#include "sim/scenes/task_tightness.h"

namespace topay {

/// One benchmark planning task: from a whole-body start state to an end-effector goal pose.
struct PlanningTask {
  WholeBodyState start;
  /// The whole-body state the goal was generated from: a hint (one feasible configuration),
  /// not a requirement; the planner's target is X_WE_goal.
  WholeBodyState goal;
  /// Goal pose of the end-effector frame E in W: FK(goal) at generation time.
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();
  DistanceRange range = DistanceRange::kSmall;
  std::uint64_t seed = 0;        ///< Seed the task (base poses, arm configurations) came from.
  std::uint64_t scene_seed = 0;  ///< Seed of the scene it was made in (0: hand-made scene).
  /// Straight-line distance between the start and goal base positions, |p_goal - p_start|.
  double base_distance_m = 0.0;
  /// Tight tasks (TaskTightness::kTight): how close each end is to the boxes and what the
  /// goal is near. Unset for an open task.
  std::optional<TightTaskInfo> tight;
};

}  // namespace topay
