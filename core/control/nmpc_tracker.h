#pragma once

#include <cstdint>

#include "core/control/control_command.h"
#include "core/control/latency_prediction.h"
#include "core/control/nmpc_options.h"
#include "core/control/nmpc_solver.h"
#include "core/control/reference_horizon.h"
#include "core/control/safe_stop.h"
#include "core/control/tracker_limits.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// The trajectory the tracker follows: its id, its start on the tracker's clock and a way
/// to sample it (an empty sampler: none).
struct TrackerReference {
  std::int64_t trajectory_id = 0;
  double start_time_s = 0.0;   ///< Time of the trajectory's t = 0 on the tracker's clock.
  double duration_s = 0.0;
  TrajectorySampler sampler;
};

/// One control cycle's inputs (times on one clock, seconds).
struct TrackerInput {
  double now_s = 0.0;
  const WholeBodyState* state = nullptr;      ///< The latest robot state (nullptr: none yet).
  double state_time_s = 0.0;                  ///< Its time.
  const TrackerReference* reference = nullptr;  ///< nullptr or an empty sampler: none.
};

/// One control cycle's result: the command and what the status reports.
struct TrackerOutput {
  ControlCommand command;
  TrackerMode mode = TrackerMode::kStopNoReference;
  std::int64_t trajectory_id = 0;  ///< The reference tracked (0 when stopping without one).
  double t_along_s = 0.0;          ///< Now - the reference's start.
  double position_error_m = 0.0;   ///< Measured state vs the reference at the state's time.
  double yaw_error_rad = 0.0;      ///< Wrapped.
  double joint_error_rad = 0.0;    ///< Largest joint error.
  double solve_ms = 0.0;           ///< This cycle's NMPC solve (0 when stopping).
  /// How far the arm's reference time is behind the clock, waiting for a base that lags (s; 0
  /// on the clock or when not tracking; NmpcOptions::arm_pacing).
  double arm_lag_s = 0.0;
};

/// The tracker's cycle, pure logic around NmpcSolver (the process in procs/tracker calls
/// Step at 50 Hz and publishes the command and the status):
///   1. the mode (ChooseTrackerMode): stale or missing state, no reference or an ended one
///      -> StopStep from the last command (within the acceleration limits, to zero);
///   2. a new trajectory id resets the solver's warm start; the first input stays within
///      one control period's rate of the last command (no jump);
///   3. latency compensation: the measured state is predicted from its time to now +
///      latency_s with the commands already sent (PredictState), and the reference is
///      sampled from that time on; while the base lags its reference by more than the slack,
///      the arm's reference is held at the configuration of the base's progress (ArmPacedTime,
///      at most the window behind the clock, never back on one trajectory; HoldArmReference);
///   4. the solve; its first input is the command, remembered with its time.
/// Allocation-free after construction apart from Ceres's own solve and the sampler.
class NmpcTracker {
 public:
  NmpcTracker(const NmpcOptions& options, const TrackerLimits& limits);

  const TrackerOutput& Step(const TrackerInput& input);
  /// The robot was stopped outside the tracker (its drives quick-stopped and held at zero):
  /// the last command and the commands remembered for the latency prediction become zero and
  /// the next trajectory starts from rest (without it, Step would ramp down from the command
  /// before the stop, commanding motion to a robot at rest).
  void Halt();
  /// The robot moves at `command` (its measured rates, or a command sent elsewhere): the next
  /// cycle's rate terms continue from it and the latency prediction forgets the commands it
  /// had (none of them moved this robot). The next trajectory starts without a warm start and
  /// with the arm's pacing from the robot's own progress.
  /// command must have num_joints joint rates.
  void ContinueFrom(const ControlCommand& command);

  const ControlCommand& last_command() const { return last_; }
  const NmpcSolver& solver() const { return solver_; }

 private:
  void Stop();
  void Track(const TrackerInput& input);
  void MeasureErrors(const TrackerInput& input);

  NmpcSolver solver_;
  CommandHistory history_;
  ControlCommand last_;
  std::int64_t active_id_ = 0;
  std::int64_t arm_paced_id_ = 0;  ///< The trajectory arm_time_s_ belongs to.
  double arm_time_s_ = 0.0;        ///< The arm's reference time on it (never back).
  ReferenceHorizon horizon_;
  TrajectorySample scratch_;
  WholeBodyState predicted_;
  TrackerOutput output_;
};

}  // namespace topay
