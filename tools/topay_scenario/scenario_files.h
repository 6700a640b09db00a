#pragma once
// What topay-scenario writes for a pick-and-place scenario: the room (scene JSON, as
// topay-sim --scene reads it), the mission (topay-mission --mission) and scenario.json (the
// seed, the goals' states and end-effector poses).

#include <string>

#include "sim/scenarios/pick_place_options.h"
#include "sim/scenarios/pick_place_scenario.h"

namespace topay::scenario {

/// scenario.json's text: {"seed", "room", "mission", "start": {x_m, y_m}, "goals": [{"name",
/// "table_top", "clearance_m", "state": {x_m, y_m, yaw_rad, q_rad}, "p_WE_m", "quat_wxyz"}]}
/// (pickup, then dropoff), numbers in shortest round-trip form.
std::string ScenarioJson(const PickPlaceScenario& scenario);

/// One line for a goal: "pickup: table top 139 (upper face 0.58 m), p_WE (x, y, z) m, base
/// (x, y) m yaw r rad, 3.2 m from the start, clearance 0.134 m".
std::string GoalLine(const char* name, const PickPlaceScenario& scenario, const TableTopGoal& goal,
                     const Eigen::Vector2d& p_W_from_m, const char* from_name);

/// Writes dir/room.json, dir/mission.yaml and dir/scenario.json (creating dir). Throws
/// ConfigError naming the file if one cannot be written.
void WriteScenarioFiles(const std::string& dir, const PickPlaceScenario& scenario,
                        const PickPlaceScenarioOptions& options);

}  // namespace topay::scenario
