#include "procs/msgs/robot_state_intake.h"

#include <utility>

namespace topay::msgs {

RobotStateIntake::RobotStateIntake(int expected_joints, const StateContinuityGateOptions& gate)
    : expected_joints_(expected_joints), gate_(gate) {}

std::optional<RobotStateEstimate> RobotStateIntake::Take(const robot_state_t& msg, std::string* error) {
  std::optional<RobotStateEstimate> estimate = FromMessage(msg, error);
  if (estimate && expected_joints_ > 0 && estimate->state.num_joints() != expected_joints_) {
    *error = std::to_string(estimate->state.num_joints()) + " joints, the robot has " + std::to_string(expected_joints_);
    estimate.reset();
  }
  if (!estimate) {
    ++malformed_;
    return std::nullopt;
  }
  last_verdict_ = gate_.Check(estimate->utime, estimate->state);
  if (!Taken(last_verdict_)) {
    *error = std::string("robot_state_t: ") + ContinuityVerdictName(last_verdict_) + ": " + gate_.last_reason();
    return std::nullopt;
  }
  return estimate;
}

bool RobotStateIntake::LogRefusal() const {
  std::int64_t n = refused();
  if (n <= 3) return true;
  while (n % 10 == 0) n /= 10;
  return n == 1;
}

std::string RobotStateIntake::Report() const {
  return std::to_string(malformed_) + " malformed; " + FormatStateContinuitySummary(gate_.summary());
}

}  // namespace topay::msgs
