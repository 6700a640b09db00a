#pragma once
// The target of `goal-in-obstacle`: the centre of a box near the robot, one it has most likely
// seen. A box anywhere in the room may be missing from the map (behind walls, not yet in view);
// the planner then cannot refuse the goal, plans towards it, and the mission's own goal replaces
// it before any ruling (fault campaign of 2026-12-07, room seed 5). Near the robot the box's
// surfaces are mapped, but its inside still may not be (a LiDAR sees surfaces only): finding 35,
// docs/reliability.md; the episode then counts the replacement (fault_episode.cc).

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
