#include "sim/motors/wheel_controller_node.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "drivers/base/fault_frame.h"
#include "drivers/base/frame_bytes.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"
#include "sim/motors/node_output.h"

namespace topay::sim::motors {
namespace {

// Periodic frames are due at their time up to this (times are sums of step periods).
constexpr double kTimeEpsilonS = 1e-9;


// The wheel angle as an encoder count modulo 2^24 (forward counts up). The angle is first taken
// modulo the angle of 2^24 counts, so that any finite angle converts; a non-finite one (a broken
// plant state) counts 0 (found by the motorsim_inputs fuzz target: -inf cast to an integer).
std::uint32_t Ticks(double angle_rad, int ticks_per_rev) {
  if (!std::isfinite(angle_rad)) return 0;
  const double wrap_rad = 2.0 * std::numbers::pi * static_cast<double>(base::kTickCountModulus) / ticks_per_rev;
  const double wrapped_rad = std::fmod(angle_rad, wrap_rad);
  const auto ticks = static_cast<std::int64_t>(std::floor(wrapped_rad / (2.0 * std::numbers::pi) * ticks_per_rev));
  return static_cast<std::uint32_t>(ticks & static_cast<std::int64_t>(base::kTickCountModulus - 1));
}

}  // namespace

std::string CheckWheelControllerOptions(const WheelControllerOptions& o) {
  if (std::string bad = base::CheckNodeId(o.node_id); !bad.empty()) return "node_id: " + bad;
  if (std::string bad = base::CheckDriveGeometry(o.geometry); !bad.empty()) return bad;
  if (std::string bad = base::CheckModeStateMachineOptions(o.modes); !bad.empty()) return bad;
  if (!PositiveFinite(o.status_period_s)) return "status_period_s must be finite and > 0";
  if (!PositiveFinite(o.feedback_period_s)) return "feedback_period_s must be finite and > 0";
  if (!std::isfinite(o.battery_voltage_v) || o.battery_voltage_v < 0.0 || o.battery_voltage_v > 100.0) {
    return "battery_voltage_v must be in 0..100 V";
  }
  if (!PositiveFinite(o.max_wheel_speed_radps) || o.max_wheel_speed_radps > 30.0) {
    return "max_wheel_speed_radps must be in (0, 30] rad/s (the wheel speeds frame's range)";
  }
  if (!PositiveFinite(o.quick_stop_decel_mps2)) return "quick_stop_decel_mps2 must be finite and > 0";
  if (!PositiveFinite(o.quick_stop_decel_radps2)) return "quick_stop_decel_radps2 must be finite and > 0";
  return "";
}

WheelControllerNode::WheelControllerNode(const WheelControllerOptions& options, double start_time_s)
    : options_(options),
      modes_(options.modes, start_time_s),
      last_step_s_(start_time_s),
      next_status_s_(start_time_s),
      next_feedback_s_(start_time_s) {
  if (std::string bad = CheckWheelControllerOptions(options); !bad.empty()) {
    throw std::invalid_argument("WheelControllerOptions: " + bad);
  }
}

const WheelControllerCounts& WheelControllerNode::counts() const {
  counts_.timeouts = modes_.timeout_count();
  return counts_;
}

bool WheelControllerNode::OnFrame(const can::CanFrame& frame, double time_s) {
  const std::optional<base::BaseFrameKind> kind = base::IdentifyFrame(frame, options_.node_id, nullptr);
  if (kind == base::BaseFrameKind::kModeRequest) {
    OnModeRequest(frame, time_s);
    return true;
  }
  if (kind == base::BaseFrameKind::kVelocityCommand) {
    OnVelocityCommand(frame, time_s);
    return true;
  }
  return false;  // not ours, or a base -> host frame (another controller's echo)
}

void WheelControllerNode::OnModeRequest(const can::CanFrame& frame, double time_s) {
  std::string error;
  const std::optional<base::ModeRequest> request = base::DecodeModeRequest(frame, options_.node_id, &error);
  if (!request) {
    ++counts_.malformed;
    last_error_ = error;
    return;
  }
  const base::BaseMode before = modes_.mode();
  error = modes_.Request(*request, time_s);
  if (!error.empty()) {
    ++counts_.mode_refused;
    last_error_ = error;
    return;
  }
  ++counts_.mode_requests;
  if (before != base::BaseMode::kCanCommand && modes_.mode() == base::BaseMode::kCanCommand) {
    target_ = {};  // a fresh CAN command mode starts from standstill until a command comes
  }
}

void WheelControllerNode::OnVelocityCommand(const can::CanFrame& frame, double time_s) {
  std::string error;
  const std::optional<base::VelocityCommand> command =
      base::DecodeVelocityCommand(frame, options_.node_id, last_command_counter_, &error);
  if (!command) {
    ++counts_.malformed;
    last_error_ = error;
    return;
  }
  if (last_command_counter_) counts_.counter_gaps += base::CounterGap(*last_command_counter_, command->counter);
  last_command_counter_ = command->counter;
  if (!modes_.AcceptVelocityCommand(time_s).empty()) {
    ++counts_.commands_ignored;
    return;
  }
  ++counts_.commands;
  // The motors saturate: both wheels scaled together (the commanded curvature kept).
  const base::UnicycleVelocity wanted{command->v_m_per_s, command->omega_rad_per_s};
  const base::WheelSpeeds wheels = base::UnicycleToWheelSpeeds(wanted, options_.geometry);
  const double top = std::max(std::abs(wheels.left_rad_per_s), std::abs(wheels.right_rad_per_s));
  const double scale = top > options_.max_wheel_speed_radps ? options_.max_wheel_speed_radps / top : 1.0;
  target_ = {wanted.v_m_per_s * scale, wanted.omega_rad_per_s * scale};
}

void WheelControllerNode::RaiseFault(base::BaseFault fault, double time_s) {
  modes_.RaiseFault(fault, time_s);
  fault_to_report_ = fault;
  ++counts_.faults;
}

void WheelControllerNode::UpdateOutput(double dt_s) {
  switch (modes_.mode()) {
    case base::BaseMode::kCanCommand:
      output_ = target_;
      return;
    case base::BaseMode::kQuickStop:
      output_.v_m_per_s = RampTowardsZero(output_.v_m_per_s, options_.quick_stop_decel_mps2 * dt_s);
      output_.omega_rad_per_s = RampTowardsZero(output_.omega_rad_per_s, options_.quick_stop_decel_radps2 * dt_s);
      return;
    case base::BaseMode::kStandby:  // motors enabled at zero speed
    case base::BaseMode::kFault:    // motors disabled: the plant's brake holds the robot
      output_ = {};
      return;
  }
}

void WheelControllerNode::IntegrateWheels(double dt_s, const base::UnicycleVelocity& plant) {
  const base::WheelSpeeds wheels = base::UnicycleToWheelSpeeds(plant, options_.geometry);
  const double left_rad = left_rad_ + wheels.left_rad_per_s * dt_s;
  const double right_rad = right_rad_ + wheels.right_rad_per_s * dt_s;
  if (!std::isfinite(left_rad) || !std::isfinite(right_rad)) return;  // a broken plant state: the wheels keep their angles
  left_rad_ = left_rad;
  right_rad_ = right_rad;
}

void WheelControllerNode::Step(double time_s, const std::optional<base::UnicycleVelocity>& plant,
                               std::vector<can::CanFrame>* out) {
  const double dt_s = std::max(0.0, time_s - last_step_s_);
  last_step_s_ = std::max(last_step_s_, time_s);
  modes_.Step(time_s);
  UpdateOutput(dt_s);
  if (plant) IntegrateWheels(dt_s, *plant);

  if (fault_to_report_) {
    std::string error;
    const base::FaultReport report{*fault_to_report_, modes_.mode(), modes_.fault_bits(), fault_counter_++};
    Emit(base::EncodeFault(report, options_.node_id, &error), error, out);
    fault_to_report_.reset();
  }
  if (reported_mode_ != modes_.mode() || time_s >= next_status_s_ - kTimeEpsilonS) {
    SendStatus(out);
    reported_mode_ = modes_.mode();
    next_status_s_ = time_s + options_.status_period_s;
  }
  if (plant && time_s >= next_feedback_s_ - kTimeEpsilonS) {
    SendFeedback(*plant, out);
    next_feedback_s_ = std::max(next_feedback_s_ + options_.feedback_period_s, time_s);
  }
}

void WheelControllerNode::SendStatus(std::vector<can::CanFrame>* out) {
  std::string error;
  const base::BaseStatus status{modes_.mode(), modes_.error_code(), modes_.fault_bits(), options_.battery_voltage_v,
                                status_counter_++};
  Emit(base::EncodeStatus(status, options_.node_id, &error), error, out);
}

void WheelControllerNode::SendFeedback(const base::UnicycleVelocity& plant, std::vector<can::CanFrame>* out) {
  const base::WheelSpeeds wheels = base::UnicycleToWheelSpeeds(plant, options_.geometry);
  const double limit = base::kMaxWheelSpeedRaw * 1e-3;
  std::string error;
  const base::WheelSpeedsFeedback speeds{std::clamp(wheels.left_rad_per_s, -limit, limit),
                                         std::clamp(wheels.right_rad_per_s, -limit, limit), speeds_counter_++};
  Emit(base::EncodeWheelSpeeds(speeds, options_.node_id, &error), error, out);
  const int ticks_per_rev = options_.geometry.ticks_per_rev;
  const base::OdometryFeedback odometry{Ticks(left_rad_, ticks_per_rev), Ticks(right_rad_, ticks_per_rev),
                                        odometry_counter_++};
  Emit(base::EncodeOdometry(odometry, options_.node_id, &error), error, out);
}

void WheelControllerNode::Emit(const std::optional<can::CanFrame>& frame, const std::string& error,
                               std::vector<can::CanFrame>* out) {
  if (AppendFrame(frame, error, out, &last_error_)) ++counts_.frames_sent;
}

}  // namespace topay::sim::motors
