#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "sim/scenes/planning_task.h"

namespace topay {

// Task files: a JSON object
//   {"range": "medium", "seed": 12, "scene_seed": 34, "base_distance_m": 9.5,
//    "start": {"x_m": .., "y_m": .., "yaw_rad": .., "q_rad": [q1, .., qN]},
//    "goal": {...same...},
//    "goal_end_effector": {"position_m": [x, y, z], "quaternion_wxyz": [w, x, y, z]},
//    "tight": {"start": {"clearance_m": .., "box": 12, "body": "arm"}, "goal": {...same...},
//              "goal_kind": "on_table", "goal_table_top": 40}}
// goal_end_effector is X_WE_goal (position of E in W, rotation R_WE as a unit quaternion).
// "tight" (PlanningTask::tight) only for a tight task; goal_table_top is null for near_box.
// Numbers in shortest round-trip form, keys in this order: same task, same bytes.

/// Largest task file read (bytes): a task is a few hundred bytes.
inline constexpr std::size_t kMaxTaskJsonBytes = std::size_t{1} << 20;  // 1 MiB

std::string TaskToJson(const PlanningTask& task);

/// The "tight" object of a task file (also a tasks.jsonl key of topay-bench).
nlohmann::ordered_json TightInfoToJson(const TightTaskInfo& info);

/// Writes TaskToJson to path; throws ConfigError(path, "", ...) if it cannot be written.
void WriteTaskJson(const std::string& path, const PlanningTask& task);

/// Reads and validates a task file. Every field above is required except "tight" (whose
/// fields are then all required, goal_table_top null exactly for near_box). Throws
/// ConfigError("<path>", "<field>", "<message>") for a missing file, a directory, a file above
/// kMaxTaskJsonBytes, malformed JSON, a missing or unknown field (at any level, e.g.
/// "start.z_m"), a wrong type, a non-finite number, an unknown range, start and goal with
/// different joint counts (or, if expected_num_joints >= 0, a count other than that), a quaternion whose
/// norm is not 1 within 1e-6, or a base_distance_m that disagrees with start and goal by more
/// than 1e-6 m.
PlanningTask ReadTaskJson(const std::string& path, int expected_num_joints = -1);

/// As ReadTaskJson, from text; file_name is used in error messages.
PlanningTask TaskFromJson(const std::string& text, const std::string& file_name,
                          int expected_num_joints = -1);

}  // namespace topay
