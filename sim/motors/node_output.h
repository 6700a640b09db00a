#pragma once
// What the simulated nodes share: a frame an encoder made (or refused) goes to the output, and
// a value ramps to zero at a deceleration.

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "drivers/can/can_frame.h"

namespace topay::sim::motors {

/// Appends `frame` to *out and returns true; when the encoder refused it (nullopt), keeps its
/// `error` in *last_error and returns false.
inline bool AppendFrame(const std::optional<can::CanFrame>& frame, const std::string& error,
                        std::vector<can::CanFrame>* out, std::string* last_error) {
  if (!frame) {
    *last_error = error;
    return false;
  }
  out->push_back(*frame);
  return true;
}

/// `value` moved towards zero by at most `max_change` (>= 0), exactly zero once within it.
inline double RampTowardsZero(double value, double max_change) {
  if (std::abs(value) <= max_change) return 0.0;
  return value - std::copysign(max_change, value);
}

/// True for a finite number > 0 (option checks).
inline bool PositiveFinite(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace topay::sim::motors
