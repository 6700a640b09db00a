#include "core/control/tracker_limits.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/option_checks.h"

namespace topay {
namespace {
constexpr const char* kTrackerLimits = "TrackerLimits";  // the owner in error messages
}  // namespace

void TrackerLimits::Check() const {
  CheckOptionPositive(kTrackerLimits, "base.v_max_mps", base.v_max_mps);
  CheckOptionPositive(kTrackerLimits, "base.a_max_mps2", base.a_max_mps2);
  CheckOptionPositive(kTrackerLimits, "base.omega_max_radps", base.omega_max_radps);
  CheckOptionPositive(kTrackerLimits, "base.beta_max_radps2", base.beta_max_radps2);
  if (qdd_max_radps2.size() != qd_max_radps.size()) {
    throw std::invalid_argument("TrackerLimits: qdd_max_radps2 has " +
                                std::to_string(qdd_max_radps2.size()) + " entries, qd_max_radps " +
                                std::to_string(qd_max_radps.size()));
  }
  for (int j = 0; j < qd_max_radps.size(); ++j) {
    CheckOptionPositive(kTrackerLimits, "qd_max_radps", qd_max_radps(j));
    CheckOptionPositive(kTrackerLimits, "qdd_max_radps2", qdd_max_radps2(j));
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
