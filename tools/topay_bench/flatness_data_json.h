#pragma once

#include <string>

#include "core/optimization/flatness_trajectory.h"

namespace topay::bench {

// Flatness-baseline trajectory files (topay-bench --dump-trajectories, method "flatness"):
// what defines the trajectory exactly (FlatnessTrajectoryData), so that it can be rebuilt
// and validated again (SampleFlatness). A JSON object
//   {"format": "topay-flatness-trajectory", "version": 1,
//    "start_yaw_rad": .., "end_yaw_rad": .., "durations_s": [T_1..T_M],
//    "head": [[pos, vel, acc] per dimension], "tail": [[pos, vel, acc] per dimension],
//    "waypoints": [[w_1..w_{M-1}] per dimension]}
// dimensions x, y, q_1..q_N (D = 2 + N rows). Numbers in shortest round-trip form.

/// The JSON text above.
std::string FlatnessDataToJson(const FlatnessTrajectoryData& data);

/// Writes FlatnessDataToJson to path; throws ConfigError(path, "", ..) if it cannot.
void WriteFlatnessDataJson(const std::string& path, const FlatnessTrajectoryData& data);

/// Reads a file written by WriteFlatnessDataJson. Throws ConfigError naming the file and the
/// field for a missing file, malformed JSON, another format or version, a missing field, a
/// non-finite number, rows of the wrong length or a duration <= 0.
FlatnessTrajectoryData ReadFlatnessDataJson(const std::string& path);

/// As ReadFlatnessDataJson, from text; file_name is used in error messages.
FlatnessTrajectoryData FlatnessDataFromJson(const std::string& text, const std::string& file_name);

}  // namespace topay::bench
