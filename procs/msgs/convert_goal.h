#pragma once
// goal_t <-> the planner's goal: the end-effector pose X_WE and an optional whole-body hint
// (the arguments of WholeBodyPlanner::Plan).

#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "core/robot/whole_body_state.h"
#include "topay/goal_t.hpp"

namespace topay::msgs {

struct PlanGoal {
  std::int64_t utime = 0;    ///< time the goal was issued, us since the Unix epoch
  std::int64_t goal_id = 0;  ///< unique per goal
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();  ///< end-effector pose in W, m
  std::optional<WholeBodyState> hint;                      ///< suggested goal configuration
};

goal_t ToMessage(const PlanGoal& goal);

/// nullopt with *error if the position is not finite, the quaternion is not finite or far from
/// unit length (|1 - |q|| > 1e-3; it is normalised otherwise) or the hint is inconsistent.
std::optional<PlanGoal> FromMessage(const goal_t& msg, std::string* error);

}  // namespace topay::msgs
