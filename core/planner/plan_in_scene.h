#pragma once

#include <optional>
#include <stop_token>

#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/map/scene_distance_fields.h"
#include "core/planner/whole_body_plan_result.h"
#include "core/planner/whole_body_planner_options.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// What PlanInScene returns: the plan and, if they were built, the fields it planned on.
struct ScenePlan {
  WholeBodyPlanResult result;
  /// Unset if the plan ended before or while building them (start or target rejected,
  /// time limit, cancel).
  std::optional<SceneDistanceFields> fields;
};

/// One plan from the exact scene, everything under options.time_limit_s (and the caller's
/// stop), in this order:
///  1. the start and the target, exactly against the scene's boxes and cheaply (a bucket grid
///     broad phase, SceneClearanceChecker): the start must be finite, of the robot's joint
///     count, within the joint limits and clear of the boxes and of itself at the validator's
///     margins; the target finite, inside the scene's bounds and not inside a box. A failure
///     is reported at once, before any field is built (timings.map_ms stays 0, fields unset);
///  2. the distance fields (field_options, default PlannerFieldOptions), stopped at the
///     deadline (then status kTimeLimit, stopped_stage kMapBuilding);
///  3. WholeBodyPlanner::PlanBy with the same deadline.
/// timings.start_check_ms and map_ms are inside timings.total_ms. Throws std::invalid_argument
/// only for bad options (as the WholeBodyPlanner constructor and BuildSceneDistanceFields);
/// bad states and poses come back as failures.
ScenePlan PlanInScene(const Kinematics& kinematics, const Scene& scene,
                      const WholeBodyPlannerOptions& options, const WholeBodyState& start,
                      const Eigen::Isometry3d& X_WE_goal,
                      const std::optional<WholeBodyState>& hint = std::nullopt,
                      std::stop_token stop = {},
                      const std::optional<SceneDistanceFieldsOptions>& field_options = std::nullopt);

}  // namespace topay
