#pragma once
// The plant's checkpoint: where the simulated robot is (X_WB, joints, gripper), written by
// topay-sim while it runs (`--checkpoint FILE`, every status period) and read when it starts, so
// that a simulator killed and restarted by the launcher continues where the robot was instead of
// putting it back at the scene's start (docs/reliability.md, finding 6). The robot restarts at
// rest; the world is the scene file's again (boxes placed by SIM_EVENT are gone).
//
// File: JSON {"utime": us, "x_m", "y_m", "yaw_rad", "q_rad": [...], "gripper"}.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/plant/plant_options.h"
#include "sim/plant/plant_state.h"

namespace topay::simproc {

struct PlantCheckpoint {
  std::int64_t utime = 0;  ///< when it was taken, us since the Unix epoch
  double x_m = 0.0, y_m = 0.0, yaw_rad = 0.0;
  std::vector<double> q_rad;
  double gripper = 0.0;  ///< 0 open .. 1 closed
};

/// The checkpoint of a plant state at utime.
PlantCheckpoint CheckpointOf(const sim::PlantState& truth, std::int64_t utime);
/// The JSON text (numbers round-trip).
std::string FormatPlantCheckpoint(const PlantCheckpoint& checkpoint);
/// Parses the text; throws ConfigError(source, field) for malformed JSON, a missing or unknown
/// key, a value not finite or a gripper outside [0, 1].
PlantCheckpoint ParsePlantCheckpoint(const std::string& text, const std::string& source);

/// Writes the file whole or not at all (a temporary file renamed over it: a kill mid-write leaves
/// the last one). Returns "" or why it could not.
std::string WritePlantCheckpoint(const std::string& path, const PlantCheckpoint& checkpoint);
/// nullopt if there is no file (the first start); the checkpoint, or ConfigError naming the file
/// and field if it is unreadable or malformed.
std::optional<PlantCheckpoint> ReadPlantCheckpoint(const std::string& path);

/// The plant's initial state from the checkpoint (X_WB, joints, gripper).
void ResumeFrom(const PlantCheckpoint& checkpoint, sim::PlantOptions* plant);

}  // namespace topay::simproc
