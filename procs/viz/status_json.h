#pragma once
// The graph's status and event messages as the viewer's JSON payloads (docs/viewer.md): each
// LCM field by name, utime as t (seconds since the Unix epoch), state constants by name.

#include <nlohmann/json.hpp>

#include "topay/drive_status_t.hpp"
#include "topay/goal_t.hpp"
#include "topay/graph_status_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/planner_paths_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::viz {

nlohmann::json PlannerStatusJson(const planner_status_t& msg);
nlohmann::json TrackerStatusJson(const tracker_status_t& msg);
nlohmann::json MissionStatusJson(const mission_status_t& msg);
nlohmann::json SimStatusJson(const sim_status_t& msg);
nlohmann::json DriveStatusJson(const drive_status_t& msg);
nlohmann::json GraphStatusJson(const graph_status_t& msg);
nlohmann::json GoalJson(const goal_t& msg);
nlohmann::json CandidatePathsJson(const planner_paths_t& msg);

}  // namespace topay::viz
