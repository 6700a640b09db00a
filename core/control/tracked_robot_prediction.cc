#include "core/control/tracked_robot_prediction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace topay {
namespace {

[[noreturn]] void Refuse(const std::string& what) {
  throw std::invalid_argument("TrackedRobotPredictor: " + what);
}

void CheckRobot(const MeasuredRobot& robot, int num_joints, double until_s) {
  if (robot.state.q_rad.size() != num_joints || robot.rates.qd_radps.size() != num_joints) {
    Refuse("robot.state.q_rad and robot.rates.qd_radps need " + std::to_string(num_joints) + " joints (the limits')");
  }
  const std::pair<const char*, bool> finite[] = {
      {"robot.state.x_m", std::isfinite(robot.state.x_m)},
      {"robot.state.y_m", std::isfinite(robot.state.y_m)},
      {"robot.state.yaw_rad", std::isfinite(robot.state.yaw_rad)},
      {"robot.state.q_rad", robot.state.q_rad.allFinite()},
      {"robot.state_time_s", std::isfinite(robot.state_time_s)},
      {"robot.rates.v_mps", std::isfinite(robot.rates.v_mps)},
      {"robot.rates.omega_radps", std::isfinite(robot.rates.omega_radps)},
      {"robot.rates.qd_radps", robot.rates.qd_radps.allFinite()}};
  for (const auto& [field, ok] : finite) {
    if (!ok) Refuse(std::string(field) + " is not finite");
  }
  if (!(until_s >= robot.state_time_s)) Refuse("until_s is before robot.state_time_s");
}

// The ideal plant over one period: the unicycle with the mid-step yaw (RolloutUnicycle's
// step), the joints integrating their rates. Not AdvanceUnicycle (core/robot/unicycle_motion.h):
// it wraps the yaw, and the predicted start must stay continuous with the robot's own yaw.
void Advance(const ControlCommand& command, double dt_s, WholeBodyState* state) {
  const double theta = state->yaw_rad + 0.5 * command.omega_radps * dt_s;
  state->x_m += command.v_mps * dt_s * std::cos(theta);
  state->y_m += command.v_mps * dt_s * std::sin(theta);
  state->yaw_rad += command.omega_radps * dt_s;
  state->q_rad += dt_s * command.qd_radps;
}

// The sample of the robot: its state, the command's rates and their change over dt_s (the
// control period: each command's rates are limited against the one before, one period
// earlier; 0: no change yet).
void Describe(const WholeBodyState& state, const ControlCommand& command, const ControlCommand& previous,
              double t_s, double dt_s, TrajectorySample* out) {
  out->t_s = t_s;
  out->state.x_m = state.x_m;
  out->state.y_m = state.y_m;
  out->state.yaw_rad = state.yaw_rad;
  out->state.q_rad = state.q_rad;
  out->v_mps = command.v_mps;
  out->omega_radps = command.omega_radps;
  out->qd_radps = command.qd_radps;
  out->a_mps2 = dt_s > 0.0 ? (command.v_mps - previous.v_mps) / dt_s : 0.0;
  out->beta_radps2 = dt_s > 0.0 ? (command.omega_radps - previous.omega_radps) / dt_s : 0.0;
  if (dt_s > 0.0) {
    out->qdd_radps2 = (command.qd_radps - previous.qd_radps) / dt_s;
  } else {
    out->qdd_radps2.setZero(command.qd_radps.size());
  }
}

}  // namespace

NmpcOptions PredictionOptions(const NmpcOptions& tracker) {
  NmpcOptions options = tracker;
  options.latency_s = 0.0;
  options.time_budget_s = 1.0;
  return options;
}

TrackedRobotPredictor::TrackedRobotPredictor(const NmpcOptions& options, const TrackerLimits& limits)
    : options_(PredictionOptions(options)),
      limits_(limits),
      tracker_(options_, limits_) {}

void TrackedRobotPredictor::Predict(const TrackerReference& reference, const MeasuredRobot& robot,
                                    double until_s, TrajectorySample* out,
                                    const std::function<bool(const TrajectorySample&)>& visit) {
  CheckRobot(robot, limits_.num_joints(), until_s);
  summary_ = TrackedRobotPredictionSummary{};
  tracker_.ContinueFrom(robot.rates);
  WholeBodyState state = robot.state;
  ControlCommand command = robot.rates;
  ControlCommand previous = robot.rates;
  double t_s = robot.state_time_s;
  Describe(state, command, previous, t_s, 0.0, out);
  TrackerInput input;
  input.state = &state;
  input.reference = &reference;
  while (t_s < until_s - 1e-9) {
    // The last cycle may be shorter: the robot at exactly until_s.
    const double dt_s = std::min(options_.control_period_s, until_s - t_s);
    input.now_s = t_s;
    input.state_time_s = t_s;  // the ideal plant's state is always fresh
    const TrackerOutput& step = tracker_.Step(input);
    previous = command;
    command = step.command;
    ++summary_.cycles;
    summary_.tracking_cycles += step.mode == TrackerMode::kTrack;
    Advance(command, dt_s, &state);
    t_s += dt_s;
    Describe(state, command, previous, t_s, options_.control_period_s, out);
    if (visit && !visit(*out)) break;
  }
  // The error against the reference where the prediction ended.
  if (reference.sampler) {
    TrajectorySample at = MakeTrajectorySample(limits_.num_joints());
    reference.sampler(std::clamp(t_s - reference.start_time_s, 0.0, reference.duration_s), &at);
    summary_.final_position_error_m = std::hypot(state.x_m - at.state.x_m, state.y_m - at.state.y_m);
  }
}

}  // namespace topay
