#include "sim/plant/plant.h"

#include <algorithm>
#include <cmath>

#include "core/robot/unicycle_motion.h"

namespace topay::sim {
namespace {

std::int64_t Steps(double seconds, double step_s) { return std::llround(seconds / step_s); }

}  // namespace

Eigen::VectorXd InitialJoints(const RobotModel& model, const PlantOptions& options) {
  const int n = model.num_joints();
  if (!options.initial.q_rad.empty()) {
    return Eigen::Map<const Eigen::VectorXd>(options.initial.q_rad.data(), options.initial.q_rad.size());
  }
  if (model.stow_q_rad.size() == n) return model.stow_q_rad;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
  if (model.joint_limits.q_min_rad.size() == n && model.joint_limits.q_max_rad.size() == n) {
    q = q.cwiseMax(model.joint_limits.q_min_rad).cwiseMin(model.joint_limits.q_max_rad);
  }
  return q;
}

Plant::Plant(const RobotModel& model, const PlantOptions& options, std::uint64_t seed)
    : model_(model),
      options_(options),
      rng_(seed),
      base_delay_(Steps(options.base.latency_s, options.step_s)),
      joint_delay_(Steps(options.joints.latency_s, options.step_s)),
      gripper_delay_(Steps(options.gripper.latency_s, options.step_s)),
      timeout_steps_(Steps(options.command_timeout_s, options.step_s)),
      v_lag_(options.base.v_tau_s, options.step_s),
      omega_lag_(options.base.omega_tau_s, options.step_s),
      joint_lag_(options.joints.tau_s, options.step_s) {
  const int n = model.num_joints();
  state_.state.x_m = options.initial.x_m;
  state_.state.y_m = options.initial.y_m;
  state_.state.yaw_rad = options.initial.yaw_rad;
  state_.state.q_rad = InitialJoints(model, options);
  state_.qdot_radps = Eigen::VectorXd::Zero(n);
  state_.gripper = options.initial.gripper;
  gripper_target_ = options.initial.gripper;
  joint_target_.qdot_radps = Eigen::VectorXd::Zero(n);
  slip_decay_ = std::exp(-options.step_s / options.wheels.slip_correlation_s);
  slip_drive_ = options.wheels.slip_stddev * std::sqrt(1.0 - slip_decay_ * slip_decay_);
}

std::string Plant::Command(const ActuatorCommand& command) {
  const std::string why = CheckActuatorCommand(command, model_.num_joints());
  if (!why.empty()) {
    ++counts_.commands_rejected;
    base_delay_.Push(step_, BaseTarget{});
    joint_delay_.Push(step_, JointTarget{true, Eigen::VectorXd::Zero(model_.num_joints())});
    return why;
  }
  ++counts_.commands_accepted;
  base_delay_.Push(step_, BaseTarget{false, command.v_mps, command.omega_radps});
  joint_delay_.Push(step_, JointTarget{false, command.qdot_radps});
  gripper_delay_.Push(step_, command.gripper);
  return "";
}

std::string Plant::CommandGripper(double target) {
  if (!std::isfinite(target) || target < 0.0 || target > 1.0) {
    ++counts_.commands_rejected;
    return "gripper target " + std::to_string(target) + " is not in [0, 1]";
  }
  gripper_delay_.Push(step_, target);
  return "";
}

void Plant::Step() {
  StepBase();
  StepJoints();
  StepGripper();
  ++step_;
  ++counts_.steps;
}

void Plant::StepTo(const PlantState& target) {
  state_ = target;
  drive_v_mps_ = target.v_mps;
  drive_omega_radps_ = target.omega_radps;
  slip_v_ = slip_omega_ = 0.0;
  base_braking_ = false;
  const double half_track = 0.5 * options_.wheels.track_m;
  wheel_left_rad_ += (drive_v_mps_ - drive_omega_radps_ * half_track) / options_.wheels.radius_m * options_.step_s;
  wheel_right_rad_ += (drive_v_mps_ + drive_omega_radps_ * half_track) / options_.wheels.radius_m * options_.step_s;
  ++step_;
  ++counts_.steps;
}

void Plant::StepBase() {
  if (std::optional<BaseTarget> due = base_delay_.Pop(step_)) {
    base_target_ = *due;
    if (!due->brake) base_rx_step_ = step_;
  }
  const bool timed_out = base_rx_step_ < 0 || step_ - base_rx_step_ > timeout_steps_;
  const bool brake = base_target_.brake || timed_out;
  if (brake && !base_braking_ && timed_out && !base_target_.brake) ++counts_.command_timeouts;
  base_braking_ = brake;

  const BaseLimits& limits = model_.base_limits;
  const double dt = options_.step_s;
  const double max_dv = limits.a_max_mps2 * dt, max_dw = limits.beta_max_radps2 * dt;
  if (brake) {
    drive_v_mps_ = LimitChange(drive_v_mps_, 0.0, max_dv);
    drive_omega_radps_ = LimitChange(drive_omega_radps_, 0.0, max_dw);
  } else {
    double u_v = std::clamp(base_target_.v_mps, -limits.v_max_mps, limits.v_max_mps);
    double u_w = std::clamp(base_target_.omega_radps, -limits.omega_max_radps, limits.omega_max_radps);
    // The coupled bound of a differential drive (the paper's eq. (9)): |v| / v_max +
    // |omega| / omega_max <= 1; beyond it both are scaled down together, keeping the
    // commanded curvature, as a drive that saturates its wheel speeds does.
    const double load = std::abs(u_v) / limits.v_max_mps + std::abs(u_w) / limits.omega_max_radps;
    if (load > 1.0) {
      u_v /= load;
      u_w /= load;
    }
    drive_v_mps_ = LimitChange(drive_v_mps_, v_lag_.Next(drive_v_mps_, u_v), max_dv);
    drive_omega_radps_ = LimitChange(drive_omega_radps_, omega_lag_.Next(drive_omega_radps_, u_w), max_dw);
  }

  // Wheel slip: the base moves by (1 + slip) of what the wheels drive.
  if (options_.wheels.slip_stddev > 0.0) {
    slip_v_ = slip_decay_ * slip_v_ + slip_drive_ * rng_.Normal();
    slip_omega_ = slip_decay_ * slip_omega_ + slip_drive_ * rng_.Normal();
  }
  const double v = drive_v_mps_ * (1.0 + slip_v_);
  const double w = drive_omega_radps_ * (1.0 + slip_omega_);
  state_.v_mps = v;
  state_.omega_radps = w;

  // Exact unicycle motion under constant v, omega over the step.
  AdvanceUnicycle(v, w, dt, &state_.state);

  const double half_track = 0.5 * options_.wheels.track_m;
  wheel_left_rad_ += (drive_v_mps_ - drive_omega_radps_ * half_track) / options_.wheels.radius_m * dt;
  wheel_right_rad_ += (drive_v_mps_ + drive_omega_radps_ * half_track) / options_.wheels.radius_m * dt;
}

void Plant::StepJoints() {
  if (std::optional<JointTarget> due = joint_delay_.Pop(step_)) {
    joint_target_ = std::move(*due);
    if (!joint_target_.brake) joint_rx_step_ = step_;
  }
  const bool brake = joint_target_.brake || joint_rx_step_ < 0 || step_ - joint_rx_step_ > timeout_steps_;
  const JointLimits& limits = model_.joint_limits;
  const double dt = options_.step_s;
  Eigen::VectorXd& qdot = state_.qdot_radps;
  Eigen::VectorXd& q = state_.state.q_rad;
  for (int i = 0; i < q.size(); ++i) {
    const double max_dqd = limits.qdd_max_radps2[i] * dt;
    if (brake) {
      qdot[i] = LimitChange(qdot[i], 0.0, max_dqd);
    } else {
      const double u = std::clamp(joint_target_.qdot_radps[i], -limits.qd_max_radps[i], limits.qd_max_radps[i]);
      qdot[i] = LimitChange(qdot[i], joint_lag_.Next(qdot[i], u), max_dqd);
    }
    q[i] += qdot[i] * dt;
    // Position limits: the joint stops at its end stop.
    if (q[i] < limits.q_min_rad[i]) {
      q[i] = limits.q_min_rad[i];
      qdot[i] = std::max(qdot[i], 0.0);
    } else if (q[i] > limits.q_max_rad[i]) {
      q[i] = limits.q_max_rad[i];
      qdot[i] = std::min(qdot[i], 0.0);
    }
  }
}

void Plant::StepGripper() {
  if (std::optional<double> due = gripper_delay_.Pop(step_)) gripper_target_ = *due;
  state_.gripper = LimitChange(state_.gripper, gripper_target_, options_.step_s / options_.gripper.open_time_s);
}

MeasuredActuators Plant::measured() const {
  MeasuredActuators m;
  const double half_track = 0.5 * options_.wheels.track_m;
  m.wheel_left_radps = (drive_v_mps_ - drive_omega_radps_ * half_track) / options_.wheels.radius_m;
  m.wheel_right_radps = (drive_v_mps_ + drive_omega_radps_ * half_track) / options_.wheels.radius_m;
  m.wheel_left_rad = wheel_left_rad_;
  m.wheel_right_rad = wheel_right_rad_;
  m.v_mps = drive_v_mps_;
  m.omega_radps = drive_omega_radps_;
  m.q_rad = state_.state.q_rad;
  m.qdot_radps = state_.qdot_radps;
  m.gripper = state_.gripper;
  m.braking = base_braking_;
  return m;
}

}  // namespace topay::sim
