#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "tools/topay_bench/bench_record.h"

namespace topay::bench {

// One line of tasks.jsonl: a JSON object with, in this order,
//   "task", "task_seed", "scene_seed", "scene", "range", "cell" ("tables medium tight"),
//   "method", "order",
//   "start": {"x_m", "y_m", "yaw_rad", "q_rad": [..]}, "goal_hint": {same}, "used_hint",
//   "target": {"position_m": [x, y, z], "quaternion_wxyz": [w, x, y, z]},
//   "base_distance_m", "base_unreachable",
//   "tight": the task file's "tight" object (sim/scenes/task_json.h) or null,
//   "success", "status", "failure_reason", "failure_category" (FailureCategoryName),
//   "timings_ms": {"search", "sampling", "front_end", "optimization", "wait", "total"},
//   "map_ms", "duration_s" (null without a trajectory),
//   "num_candidates", "num_paths", "num_classes", "num_base_paths", "plan_rounds",
//   "validation": {"ok", "min_clearance_m", "min_clearance_part", "min_self_clearance_m",
//                  "worst_limit_ratio", "worst_limit", "worst_limit_t_s",
//                  "end_position_error_m", "end_orientation_error_rad"} or null.
// Every wall-clock figure is under "timings_ms" or is "map_ms": without those two keys, the
// line of a deterministic run (--threads 1) is the same on every run. Non-finite numbers
// (an infinite clearance) are written as null. Seeds are unsigned 64-bit integers.

/// The record as a JSON object (ordered keys, as above).
nlohmann::ordered_json RecordToJson(const BenchRecord& record);

/// RecordToJson as one line of text, without the newline.
std::string RecordJsonLine(const BenchRecord& record);

}  // namespace topay::bench
