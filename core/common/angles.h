#pragma once

#include <cmath>
#include <numbers>

namespace topay {

/// Wraps an angle to (-pi, pi] rad.
inline double WrapAngle(double angle_rad) {
  double wrapped = std::remainder(angle_rad, 2.0 * std::numbers::pi);
  if (wrapped <= -std::numbers::pi) wrapped += 2.0 * std::numbers::pi;
  return wrapped;
}

}  // namespace topay
