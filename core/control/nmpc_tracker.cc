#include "core/control/nmpc_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/angles.h"

namespace topay {
namespace {

// Commands kept for latency prediction: enough for the latency plus a stale state's age.
int HistoryCapacity(const NmpcOptions& options) {
  return static_cast<int>(
             std::ceil((options.latency_s + options.stale_state_s) / options.control_period_s)) +
         4;
}

}  // namespace

NmpcTracker::NmpcTracker(const NmpcOptions& options, const TrackerLimits& limits)
    : solver_(options, limits),
      history_(HistoryCapacity(options), limits.num_joints()),
      last_(ControlCommand::Zero(limits.num_joints())),
      horizon_(ReferenceHorizon::Zero(options.horizon_steps, limits.num_joints())),
      scratch_(MakeTrajectorySample(limits.num_joints())),
      output_{ControlCommand::Zero(limits.num_joints())} {
  predicted_.q_rad.setZero(limits.num_joints());
}

const TrackerOutput& NmpcTracker::Step(const TrackerInput& input) {
  const bool has_reference = input.reference != nullptr && bool(input.reference->sampler);
  TrackerSituation situation;
  situation.has_reference = has_reference;
  situation.t_along_s = has_reference ? input.now_s - input.reference->start_time_s : 0.0;
  situation.reference_duration_s = has_reference ? input.reference->duration_s : 0.0;
  situation.state_age_s = input.state != nullptr ? input.now_s - input.state_time_s
                                                 : std::numeric_limits<double>::infinity();
  const TrackerMode mode = ChooseTrackerMode(situation, solver_.options());
  output_.mode = mode;
  output_.t_along_s = situation.t_along_s;
  output_.trajectory_id = has_reference ? input.reference->trajectory_id : 0;
  output_.solve_ms = 0.0;
  output_.arm_lag_s = 0.0;
  if (mode == TrackerMode::kTrack) {
    Track(input);
  } else {
    Stop();
  }
  if (input.state != nullptr && has_reference) MeasureErrors(input);
  history_.Push(input.now_s, output_.command);
  last_.v_mps = output_.command.v_mps;
  last_.omega_radps = output_.command.omega_radps;
  last_.qd_radps = output_.command.qd_radps;
  return output_;
}

void NmpcTracker::Halt() {
  last_.v_mps = 0.0;
  last_.omega_radps = 0.0;
  last_.qd_radps.setZero();
  history_.Clear();
  active_id_ = 0;
}

void NmpcTracker::ContinueFrom(const ControlCommand& command) {
  last_.v_mps = command.v_mps;
  last_.omega_radps = command.omega_radps;
  last_.qd_radps = command.qd_radps;
  history_.Clear();
  active_id_ = 0;
  arm_paced_id_ = 0;  // the arm's pacing starts again from this robot
}

void NmpcTracker::Stop() {
  StopStep(last_, solver_.options().control_period_s, solver_.limits(), &output_.command);
  // Tracking may resume later (the same or a new trajectory): start again from the command.
  active_id_ = 0;
}

void NmpcTracker::Track(const TrackerInput& input) {
  const NmpcOptions& options = solver_.options();
  const TrackerReference& reference = *input.reference;
  if (reference.trajectory_id != active_id_) {
    solver_.ResetWarmStart();  // continuity comes from the last command's rate terms
    active_id_ = reference.trajectory_id;
  }
  if (reference.trajectory_id != arm_paced_id_) {  // a new trajectory: the arm on its clock
    arm_paced_id_ = reference.trajectory_id;
    arm_time_s_ = -std::numeric_limits<double>::infinity();
  }
  // Latency compensation: the state when the command will act.
  const double act_time_s = input.now_s + options.latency_s;
  predicted_.x_m = input.state->x_m;
  predicted_.y_m = input.state->y_m;
  predicted_.yaw_rad = input.state->yaw_rad;
  predicted_.q_rad = input.state->q_rad;
  PredictState(history_, options.latency_s, input.state_time_s, act_time_s, &predicted_);
  const double clock_t_s = act_time_s - reference.start_time_s;
  SampleReferenceHorizon(reference.sampler, reference.duration_s, clock_t_s, options.step_s,
                         &scratch_, &horizon_);
  // Arm pacing: while the base lags, the arm holds the configuration of the base's progress
  // (never back on one trajectory); it moves on only to configurations whose base pose the
  // robot has reached, within the slack.
  const double paced_s = ArmPacedTime(reference.sampler, reference.duration_s, clock_t_s,
                                      predicted_, options.arm_pacing, &scratch_);
  arm_time_s_ = std::min(clock_t_s, std::max(arm_time_s_, paced_s));
  output_.arm_lag_s = clock_t_s - arm_time_s_;
  if (output_.arm_lag_s > 0.0) {
    HoldArmReference(reference.sampler, reference.duration_s, arm_time_s_, &scratch_, &horizon_);
  }
  const InputSequence& inputs = solver_.Solve(predicted_, horizon_, last_);
  inputs.CommandAt(0, &output_.command);
  output_.solve_ms = solver_.summary().solve_ms;
}

void NmpcTracker::MeasureErrors(const TrackerInput& input) {
  const TrackerReference& reference = *input.reference;
  const double t_s = std::clamp(input.state_time_s - reference.start_time_s, 0.0,
                                reference.duration_s);
  reference.sampler(t_s, &scratch_);
  const WholeBodyState& state = *input.state;
  output_.position_error_m =
      std::hypot(state.x_m - scratch_.state.x_m, state.y_m - scratch_.state.y_m);
  output_.yaw_error_rad = std::abs(WrapAngle(state.yaw_rad - scratch_.state.yaw_rad));
  output_.joint_error_rad = (state.q_rad - scratch_.state.q_rad).cwiseAbs().maxCoeff();
}

}  // namespace topay
