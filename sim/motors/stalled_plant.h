#pragma once
// The plant's state as the motors feel it while the simulator does not run (docs/motorsim.md,
// "A stalled simulator"). topay-sim publishes the plant's state every 4 ms; on a loaded machine
// its process may not run for up to a second, and then catches up on the commands of the stall
// (docs/simulator.md, "Time base"). Meanwhile the motor simulator kept answering with the last
// state it had: joints frozen where they were, wheels turning at the old speed (its odometry
// integrated that speed), so the estimate ran on while the plant braked (finding 34 in
// docs/reliability.md). Real motors are not paused by a process: this carries the last state on
// the drives' own command (the robot moving as commanded, without the plant's lag) for as long as
// the simulator catches up (carry_on_s), then holds it still, as the simulator's world pauses. A
// fresh state replaces the carried one at once. Pure: times are passed in.

#include <cstdint>
#include <optional>
#include <string>

#include "sim/plant/actuator_command.h"
#include "sim/plant/plant_state.h"

namespace topay::sim::motors {

struct StalledPlantOptions {
  double stale_after_s = 0.02;  ///< a state older than this is stale (the simulator sends one every 4 ms), s
  double carry_on_s = 1.0;      ///< carried on the command at most this long after it arrived (the simulator's catch-up), s
};

/// Empty when the options are valid, else what is wrong.
std::string CheckStalledPlantOptions(const StalledPlantOptions& options);

struct StalledPlantCounts {
  std::int64_t stalls = 0;       ///< times the state went stale
  double carried_s = 0.0;        ///< time carried on the command, in all, s
  double held_s = 0.0;           ///< time held still after carry_on_s, in all, s
  double longest_stall_s = 0.0;  ///< the longest a state stayed the latest, s
};

class StalledPlant {
 public:
  explicit StalledPlant(const StalledPlantOptions& options = {}) : options_(options) {}

  /// A state of the plant, received at time_s.
  void OnPlantState(const PlantState& state, double time_s);

  /// The state to answer with at time_s (non-decreasing), the drives commanding `command` now:
  /// the latest received while it is fresh, else that one carried forward. Null before the first.
  const PlantState* At(double time_s, const ActuatorCommand& command);

  /// True while the latest state is stale (after At).
  bool stale() const { return carried_.has_value(); }
  const StalledPlantCounts& counts() const { return counts_; }

 private:
  /// Moves carried_ from carried_time_s_ to end_s on `command`.
  void Carry(double end_s, const ActuatorCommand& command);

  StalledPlantOptions options_;
  std::optional<PlantState> latest_;
  double received_s_ = 0.0;
  std::optional<PlantState> carried_;
  double carried_time_s_ = 0.0;
  double last_time_s_ = 0.0;
  StalledPlantCounts counts_;
};

}  // namespace topay::sim::motors
