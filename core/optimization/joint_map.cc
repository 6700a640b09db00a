#include "core/optimization/joint_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/optimization/time_map.h"

namespace topay {

double JointFromXi(double xi, double q_min_rad, double q_max_rad, double* dq_dxi) {
  double dr_dxi = 0.0;
  const double r = DurationFromTau(xi, dq_dxi ? &dr_dxi : nullptr);
  const double one_plus_r = 1.0 + r;
  // Eq. (22) inverted: q = (q_min + q_max r) / (1 + r).
  if (dq_dxi) *dq_dxi = (q_max_rad - q_min_rad) / (one_plus_r * one_plus_r) * dr_dxi;
  return (q_min_rad + q_max_rad * r) / one_plus_r;
}

double XiFromJoint(double q_rad, double q_min_rad, double q_max_rad, double interior_fraction) {
  if (!std::isfinite(q_rad)) {
    throw std::invalid_argument("XiFromJoint: joint value " + std::to_string(q_rad) +
                                " is not finite");
  }
  if (!(std::isfinite(q_min_rad) && std::isfinite(q_max_rad) && q_min_rad < q_max_rad)) {
    throw std::invalid_argument("XiFromJoint: limits [" + std::to_string(q_min_rad) + ", " +
                                std::to_string(q_max_rad) + "] are not finite with min < max");
  }
  if (!(interior_fraction > 0.0 && interior_fraction < 0.5)) {
    throw std::invalid_argument("XiFromJoint: interior_fraction " +
                                std::to_string(interior_fraction) + " not in (0, 0.5)");
  }
  const double e = interior_fraction * (q_max_rad - q_min_rad);
  const double q = std::clamp(q_rad, q_min_rad + e, q_max_rad - e);
  // Eq. (22): xi = L_c2((q - q_min) / (q_max - q)).
  return TauFromDuration((q - q_min_rad) / (q_max_rad - q));
}

}  // namespace topay
