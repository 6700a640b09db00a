#pragma once
// ROBOT_STATE as every consumer takes it (planner, tracker, mapper, mission, director): decoded
// (FromMessage: arrays match, values finite), the robot's joint count, then the continuity
// gate (core/estimation/state_continuity_gate.h: stamped after the last state taken, within the
// robot's limits of it, or a consistent new stream after a real jump). A corrupted, repeated or
// reordered message is refused with its reason instead of moving the robot's state
// (docs/reliability.md, finding 9).

#include <cstdint>
#include <optional>
#include <string>

#include "core/estimation/state_continuity_gate.h"
#include "procs/msgs/convert_robot_state.h"
#include "topay/robot_state_t.hpp"

namespace topay::msgs {

class RobotStateIntake {
 public:
  /// expected_joints: the robot's arm (0 accepts any count). Throws std::invalid_argument for
  /// bad gate options.
  explicit RobotStateIntake(int expected_joints, const StateContinuityGateOptions& gate = {});

  /// The state to use, or nullopt with *error naming what was wrong ("robot_state_t.pose: not
  /// finite", "8 joints, the robot has 7", or the gate's reason).
  std::optional<RobotStateEstimate> Take(const robot_state_t& msg, std::string* error);

  /// The gate's verdict on the last decodable message (kTaken before any).
  ContinuityVerdict last_verdict() const { return last_verdict_; }
  /// Messages refused: malformed or the wrong joint count, and by the gate.
  std::int64_t malformed() const { return malformed_; }
  std::int64_t refused() const { return malformed_ + gate_.summary().refused(); }
  const StateContinuityGateSummary& gate_summary() const { return gate_.summary(); }
  /// Whether the last refusal is worth a log line: the first three, then the 10th, 100th, ...
  /// (a hostile or broken stream is counted, not logged at 100 Hz).
  bool LogRefusal() const;
  /// The gate's reason for the last verdict (for a re-anchor: what the jump was).
  const std::string& gate_reason() const { return gate_.last_reason(); }
  /// "N malformed; <the gate's summary>".
  std::string Report() const;

 private:
  int expected_joints_;
  StateContinuityGate gate_;
  ContinuityVerdict last_verdict_ = ContinuityVerdict::kTaken;
  std::int64_t malformed_ = 0;
};

}  // namespace topay::msgs
