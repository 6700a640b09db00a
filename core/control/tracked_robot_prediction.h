#pragma once
// Where the tracker will have brought a robot that is off its trajectory (finding 34,
// docs/reliability.md; docs/control.md "Predicting the tracked robot").
//
// A planner that replans for drift starts the new trajectory where the robot will be when it
// takes over (t0, a replanning budget ahead). Carrying the robot's error along the trajectory
// unchanged (the planner's DriftedRobot) assumes the tracker keeps the error; it closes it, so
// under overload the new trajectories started 0.26-0.3 m and 0.3 rad from where the robot then
// was, and the tracker had a new error to close. This runs the tracker itself (NmpcTracker) in
// closed loop on an ideal plant from the measured state, which is what the robot will do.

#include <functional>

#include "core/control/control_command.h"
#include "core/control/nmpc_options.h"
#include "core/control/nmpc_tracker.h"
#include "core/control/tracker_limits.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// The measured robot a prediction starts from: its state and its rates at state_time_s (on
/// the reference's clock, s).
struct MeasuredRobot {
  WholeBodyState state;
  double state_time_s = 0.0;
  ControlCommand rates;  ///< v, omega, joint rates (num_joints); taken as the last command.
};

/// What a prediction did (the last one's; for reports and tests).
struct TrackedRobotPredictionSummary {
  int cycles = 0;               ///< Tracker cycles run.
  int tracking_cycles = 0;      ///< Of them, in TrackerMode::kTrack (the others stopping).
  double final_position_error_m = 0.0;  ///< The predicted robot against the reference at until_s.
};

/// NmpcTracker in closed loop on an ideal plant: the base a unicycle (RolloutUnicycle's
/// mid-step integration) and the joints integrators, each command followed exactly over one
/// control period. Two departures from the process, both so that the prediction depends only
/// on its inputs: the latency is left out (the ideal plant acts at once, so there is nothing
/// to predict over), and the time budget is lifted (a solve ends on its iteration limit, not
/// on how loaded the machine is). Not thread-safe; allocation-free per cycle apart from
/// Ceres's own solve and the sampler.
class TrackedRobotPredictor {
 public:
  /// Throws std::invalid_argument for bad options or limits (NmpcSolver's checks).
  TrackedRobotPredictor(const NmpcOptions& options, const TrackerLimits& limits);

  /// The robot at until_s (on the reference's clock, >= robot.state_time_s) as the tracker
  /// will have brought it along `reference`, into *out (sized for the joints): state, the rates
  /// of the last command (v, omega, qd) and their change over the last period (a, beta, qdd),
  /// t_s = until_s. A reference that ends (or a robot state the tracker would take as stale)
  /// is handled as the tracker does: it brakes within the limits. `visit` (optional) sees the
  /// predicted robot after every cycle, at its time, and may end the prediction early by
  /// returning false (*out is then that cycle's robot). Throws std::invalid_argument naming the
  /// field for a joint count other than the limits', a non-finite state or rate, or
  /// until_s < state_time_s.
  void Predict(const TrackerReference& reference, const MeasuredRobot& robot, double until_s,
               TrajectorySample* out,
               const std::function<bool(const TrajectorySample&)>& visit = nullptr);

  const TrackedRobotPredictionSummary& summary() const { return summary_; }

 private:
  NmpcOptions options_;
  TrackerLimits limits_;
  NmpcTracker tracker_;
  TrackedRobotPredictionSummary summary_;
};

/// The prediction's options from the tracker's: latency 0, the time budget lifted to 1 s.
NmpcOptions PredictionOptions(const NmpcOptions& tracker);

}  // namespace topay
