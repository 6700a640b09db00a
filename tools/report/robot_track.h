#pragma once
// The robot's base over the run, from ROBOT_STATE (log order, which is time order).

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "procs/msgs/convert_robot_state.h"

namespace topay::report {

/// p_WB of every state, in order.
std::vector<Eigen::Vector2d> DrivenPath(const std::vector<msgs::RobotStateEstimate>& states);

/// p_WB of the state closest in time to utime; nullopt without states.
std::optional<Eigen::Vector2d> BasePositionAt(const std::vector<msgs::RobotStateEstimate>& states,
                                              std::int64_t utime);

}  // namespace topay::report
