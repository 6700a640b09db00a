#pragma once
// The target of `goal-in-obstacle`: a box's centre the robot has most likely seen. A box
// anywhere in the room may still be missing from the map (behind walls, not yet in view); the
// planner then cannot refuse the goal, plans towards it, and the mission's own goal replaces it
// before any ruling (fault campaign of 2026-12-07, room seed 5: the episode waited for a
// refusal that could not come). The boxes near the robot are in its map.

#include <optional>
#include <random>
#include <vector>

#include <Eigen/Core>

namespace topay::tools {

/// One of `box_centers_m` (not empty) chosen at random among those whose centre is within
/// near_m (horizontally) of p_robot_m; none that near: the nearest; no robot position yet:
/// any. Throws std::invalid_argument for no boxes.
Eigen::Vector3d ChooseObstacleGoal(const std::vector<Eigen::Vector3d>& box_centers_m,
                                   const std::optional<Eigen::Vector2d>& p_robot_m, double near_m,
                                   std::mt19937_64* random);

}  // namespace topay::tools
