#pragma once
// The checks a goal passes before the planner spends time on it (each failure is reported at
// once, PLANNER_STATUS FAILED with the reason): a target outside the map's volume, out of
// the arm's height range from any base pose, inside (or within a clearance of) a voxel the
// planner counts as an obstacle, or inside a body the LiDAR saw only from outside (an unseen
// pocket: core/map/unseen_pocket.h, goals.unseen_pocket_reach_m). Malformed goals (NaN, a quaternion far from unit length,
// a bad hint) are refused earlier, by the message conversion (msgs::FromMessage).

#include <string>

#include <Eigen/Core>

#include "core/optimization/trajectory_problem.h"
#include "procs/msgs/convert_goal.h"
#include "procs/planner/map_intake.h"
#include "procs/planner/planner_process_options.h"

namespace topay::planner {

/// "" if the goal may be planned for, else the reason (naming the value).
std::string ScreenGoal(const msgs::PlanGoal& goal, const MapIntake& map, const ReachHeights& reach,
                       const GoalCheckOptions& options);

/// ScreenGoal's checks of the target p_WT against the map (outside it, blocked, in an unseen
/// pocket), also run on a goal in hand as the map changes. "" before the first map.
std::string ScreenTargetInMap(const Eigen::Vector3d& p_WT, const MapIntake& map, const GoalCheckOptions& options);

}  // namespace topay::planner
