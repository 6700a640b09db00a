#pragma once

#include <string>

#include "tools/topay_plan/trajectory_record.h"

namespace topay::plan {

// Trajectory files (topay-plan --json): one JSON object
//   {"format": "topay-trajectory", "version": 1,
//    "metadata": {"scene": {"kind", "seed", "file", "num_boxes"},
//                 "task": {"source", "file", "range", "seed", "start", "goal_end_effector"},
//                 "base_limits": {"source", "v_max_mps", ...}, "plan": {"status",
//                 "failure_reason", "timings_ms": {"map_build", "search", ...}},
//                 "validation": {...} or null},
//    "trajectory": {"dimensions": ["s", "yaw", "q1", ..], "p0_m": [x0, y0],
//                   "panels_per_piece": 12, "duration_s": T,
//                   "pieces": [{"duration_s": T_j, "coefficients": [[c0..c5] per dimension]}]}
//                  or null when the plan failed,
//    "samples": {"period_s": 0.01, "count": n, "units": {key: unit, ..},
//                "rows": [{"t", "x", "y", "yaw", "s", "v", "omega", "a", "beta",
//                          "q": [..]}, ..]}}   (docs/formats.md)
// Piece j of dimension d is value(t) = sum_k c_k t^k for the local time t in [0, T_j]
// (paper eqs. (3)-(5), quintic, MINCO s = 3); dimensions in the order [s, yaw, q1..qN]. x and
// y follow from s and yaw by Simpson's rule with panels_per_piece panels per piece (eqs.
// (1)-(2)), starting at p0_m. Samples are at t = 0, period, 2 period, ... and at the exact
// end. Numbers are in shortest round-trip form (reading gives back the same doubles);
// non-finite figures (an infinite clearance, an unmeasured error) are written as null. One
// piece and one sample per line.

/// The JSON text described above.
std::string TrajectoryToJson(const TrajectoryFile& file);

/// Writes TrajectoryToJson to path; throws ConfigError(path, "", ...) if it cannot be written.
void WriteTrajectoryJson(const std::string& path, const TrajectoryFile& file);

/// Reads and validates a trajectory file. Throws ConfigError("<path>", "<field>", "<message>")
/// for a missing file, malformed JSON, another format or version, a missing field, a wrong
/// type, a non-finite number where one is required, a piece that is not 2 + N rows of 6
/// coefficients or has a duration <= 0, a sample whose q_rad does not have N entries (N from
/// metadata.task.start), or sample times that do not increase.
TrajectoryFile ReadTrajectoryJson(const std::string& path);

/// As ReadTrajectoryJson, from text; file_name is used in error messages.
TrajectoryFile TrajectoryFromJson(const std::string& text, const std::string& file_name);

}  // namespace topay::plan
