#include "core/control/tracker_limits.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

void CheckPositive(double value, const char* field) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string("TrackerLimits: ") + field +
                                " must be finite and > 0, got " + std::to_string(value));
  }
}

}  // namespace

void TrackerLimits::Check() const {
  CheckPositive(base.v_max_mps, "base.v_max_mps");
  CheckPositive(base.a_max_mps2, "base.a_max_mps2");
  CheckPositive(base.omega_max_radps, "base.omega_max_radps");
  CheckPositive(base.beta_max_radps2, "base.beta_max_radps2");
  if (qdd_max_radps2.size() != qd_max_radps.size()) {
    throw std::invalid_argument("TrackerLimits: qdd_max_radps2 has " +
                                std::to_string(qdd_max_radps2.size()) + " entries, qd_max_radps " +
                                std::to_string(qd_max_radps.size()));
  }
  for (int j = 0; j < qd_max_radps.size(); ++j) {
    CheckPositive(qd_max_radps(j), "qd_max_radps");
    CheckPositive(qdd_max_radps2(j), "qdd_max_radps2");
  }
}

TrackerLimits MakeTrackerLimits(const RobotModel& robot) {
  TrackerLimits limits;
  limits.base = robot.base_limits;
  limits.qd_max_radps = robot.joint_limits.qd_max_radps;
  limits.qdd_max_radps2 = robot.joint_limits.qdd_max_radps2;
  limits.coupled_v_omega = true;
  limits.Check();
  return limits;
}

}  // namespace topay
