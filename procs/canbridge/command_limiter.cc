#include "procs/canbridge/command_limiter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace topay::canbridge {

CommandLimits CommandLimitsOf(const RobotModel& model) {
  CommandLimits limits;
  limits.v_max_mps = model.base_limits.v_max_mps;
  limits.a_max_mps2 = model.base_limits.a_max_mps2;
  limits.omega_max_radps = model.base_limits.omega_max_radps;
  limits.beta_max_radps2 = model.base_limits.beta_max_radps2;
  const Eigen::VectorXd& qd = model.joint_limits.qd_max_radps;
  const Eigen::VectorXd& qdd = model.joint_limits.qdd_max_radps2;
  limits.qd_max_radps.assign(qd.data(), qd.data() + qd.size());
  limits.qdd_max_radps2.assign(qdd.data(), qdd.data() + qdd.size());
  return limits;
}

std::string CheckControlCommand(const control_command_t& msg, int num_joints) {
  if (msg.num_joints != num_joints) {
    return "num_joints " + std::to_string(msg.num_joints) + ", expected " + std::to_string(num_joints);
  }
  if (static_cast<int>(msg.qdot_radps.size()) != msg.num_joints) return "qdot_radps size differs from num_joints";
  if (!std::isfinite(msg.v_mps)) return "v_mps is not finite";
  if (!std::isfinite(msg.omega_radps)) return "omega_radps is not finite";
  for (int i = 0; i < msg.num_joints; ++i) {
    if (!std::isfinite(msg.qdot_radps[i])) return "qdot_radps[" + std::to_string(i) + "] is not finite";
  }
  return "";
}

DeviceCommand ToDeviceCommand(const control_command_t& msg) {
  return DeviceCommand{msg.v_mps, msg.omega_radps, msg.qdot_radps};
}

bool IsZeroCommand(const DeviceCommand& command, double tolerance) {
  if (std::abs(command.v_mps) > tolerance || std::abs(command.omega_radps) > tolerance) return false;
  return std::all_of(command.qdot_radps.begin(), command.qdot_radps.end(),
                     [tolerance](double q) { return std::abs(q) <= tolerance; });
}

CommandLimiter::CommandLimiter(CommandLimits limits, double cycle_period_s)
    : limits_(std::move(limits)), cycle_period_s_(cycle_period_s) {
  if (limits_.qd_max_radps.size() != limits_.qdd_max_radps2.size()) {
    throw std::invalid_argument("CommandLimiter: joint velocity and acceleration limits differ in size");
  }
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  bool ok = positive(limits_.v_max_mps) && positive(limits_.a_max_mps2) && positive(limits_.omega_max_radps) &&
            positive(limits_.beta_max_radps2) && positive(cycle_period_s);
  for (std::size_t i = 0; i < limits_.qd_max_radps.size(); ++i) {
    ok = ok && positive(limits_.qd_max_radps[i]) && positive(limits_.qdd_max_radps2[i]);
  }
  if (!ok) throw std::invalid_argument("CommandLimiter: every limit and the cycle period must be finite and > 0");
  last_.qdot_radps.assign(limits_.qd_max_radps.size(), 0.0);
}

double CommandLimiter::Limit(double target, double previous, double max_abs, double max_rate, double dt_s,
                             bool* clamped) const {
  const double in_range = std::clamp(target, -max_abs, max_abs);
  const double max_change = max_rate * dt_s;
  const double limited = std::clamp(in_range, previous - max_change, previous + max_change);
  // Stay inside the range even when the previous value was outside it (never, by construction).
  const double result = std::clamp(limited, -max_abs, max_abs);
  if (result != target) *clamped = true;
  return result;
}

const DeviceCommand& CommandLimiter::Step(const DeviceCommand& target, double now_s) {
  const double dt_s = has_time_ ? std::clamp(now_s - last_time_s_, 0.0, cycle_period_s_) : cycle_period_s_;
  has_time_ = true;
  last_time_s_ = now_s;
  bool clamped = false;
  last_.v_mps = Limit(target.v_mps, last_.v_mps, limits_.v_max_mps, limits_.a_max_mps2, dt_s, &clamped);
  last_.omega_radps =
      Limit(target.omega_radps, last_.omega_radps, limits_.omega_max_radps, limits_.beta_max_radps2, dt_s, &clamped);
  for (std::size_t i = 0; i < last_.qdot_radps.size(); ++i) {
    const double q = i < target.qdot_radps.size() ? target.qdot_radps[i] : 0.0;
    last_.qdot_radps[i] =
        Limit(q, last_.qdot_radps[i], limits_.qd_max_radps[i], limits_.qdd_max_radps2[i], dt_s, &clamped);
  }
  if (clamped) ++clamp_count_;
  return last_;
}

void CommandLimiter::ResetToZero(double now_s) {
  last_.v_mps = 0.0;
  last_.omega_radps = 0.0;
  std::fill(last_.qdot_radps.begin(), last_.qdot_radps.end(), 0.0);
  last_time_s_ = now_s;
  has_time_ = true;
}

}  // namespace topay::canbridge
