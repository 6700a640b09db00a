#include "core/robot/unicycle_motion.h"

#include <cmath>
#include <numbers>

namespace topay {

void AdvanceUnicycle(double v_mps, double omega_radps, double dt_s, WholeBodyState* state) {
  WholeBodyState& s = *state;
  const double yaw_end = s.yaw_rad + omega_radps * dt_s;
  if (std::abs(omega_radps) < 1e-9) {
    s.x_m += v_mps * dt_s * std::cos(s.yaw_rad);
    s.y_m += v_mps * dt_s * std::sin(s.yaw_rad);
  } else {
    // Integral of v (cos yaw, sin yaw) dt with yaw(t) = yaw0 + omega t.
    const double radius_m = v_mps / omega_radps;
    s.x_m += radius_m * (std::sin(yaw_end) - std::sin(s.yaw_rad));
    s.y_m -= radius_m * (std::cos(yaw_end) - std::cos(s.yaw_rad));
  }
  s.yaw_rad = std::remainder(yaw_end, 2.0 * std::numbers::pi);
}

}  // namespace topay
