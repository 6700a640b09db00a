#include "core/optimization/time_map.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

double DurationFromTau(double tau, double* dT_dtau) {
  if (tau > 0.0) {
    // Eq. (21) inverted, tau > 0: T = tau^2/2 + tau + 1.
    if (dT_dtau) *dT_dtau = tau + 1.0;
    return (0.5 * tau + 1.0) * tau + 1.0;
  }
  // Eq. (21) inverted, tau <= 0: T = 1 / (tau^2/2 - tau + 1).
  const double denominator = (0.5 * tau - 1.0) * tau + 1.0;
  if (dT_dtau) *dT_dtau = (1.0 - tau) / (denominator * denominator);
  return 1.0 / denominator;
}

double TauFromDuration(double duration_s) {
  if (!(std::isfinite(duration_s) && duration_s > 0.0)) {
    throw std::invalid_argument("TauFromDuration: duration " + std::to_string(duration_s) +
                                " s is not a positive finite number");
  }
  // Eq. (21).
  if (duration_s > 1.0) return std::sqrt(2.0 * duration_s - 1.0) - 1.0;
  return 1.0 - std::sqrt(2.0 / duration_s - 1.0);
}

}  // namespace topay
