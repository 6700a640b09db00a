#pragma once

#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/planning/front_end_result.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// The cause of a front-end failure in the exact scene (core/collision/start_target_diagnosis.h),
/// for WholeBodyPlanResult::failure_reason, or nullopt if there is nothing more to say:
///  - kStartInvalid: the joint out of its limits, or the box and the robot body the start
///    collides with; if the start is exactly clear, the nearest contact within the field
///    check's margins (validity's base / arm / self margins), which is what failed.
///  - kNoGoal, kNoBasePath, kNoArmPath: a target below the floor, outside the room or inside
///    a box (which one).
std::optional<std::string> FrontEndFailureCause(FrontEndStatus status,
                                                const WholeBodyValidity& validity,
                                                const Scene& scene, const WholeBodyState& start,
                                                const Eigen::Isometry3d& X_WE_target);

}  // namespace topay
