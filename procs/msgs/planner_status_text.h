#pragma once
// The two PLANNER_STATUS reports that a goal was reached (state SUCCEEDED), in one place for
// the planner that writes them and the mission, tools and tests that read them:
//  - "trajectory N ended": the goal's last trajectory ran to its end;
//  - "goal reached at rest: end effector D m / A rad from the target": the robot stood at the
//    target when a plan from rest was due (a stop that braked along the trajectory to its end,
//    a goal sent again where the robot stands), so no plan was made.
// Every other SUCCEEDED detail is the trigger of a plan that went out (the goal under way).

#include <cstdint>
#include <string>

#include "topay/planner_status_t.hpp"

namespace topay::msgs {

/// "trajectory <trajectory_id> ended".
std::string TrajectoryEndedDetail(std::int64_t trajectory_id);
/// "goal reached at rest: end effector <position_m> m / <angle_rad> rad from the target" (3 decimals).
std::string ReachedAtRestDetail(double position_m, double angle_rad);

/// SUCCEEDED with a TrajectoryEndedDetail.
bool ReportsTrajectoryEnded(const planner_status_t& status);
/// SUCCEEDED with a ReachedAtRestDetail.
bool ReportsReachedAtRest(const planner_status_t& status);
/// Either: the planner is done with the goal and the robot stands at its end.
bool ReportsGoalReached(const planner_status_t& status);

}  // namespace topay::msgs
