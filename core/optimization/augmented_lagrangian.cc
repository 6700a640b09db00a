#include "core/optimization/augmented_lagrangian.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

void CheckAugmentedLagrangianOptions(const AugmentedLagrangianOptions& o,
                                     std::string_view owner) {
  const auto require = [owner](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string(owner) + ": alm." + what);
  };
  require(std::isfinite(o.rho_initial) && o.rho_initial > 0.0,
          "rho_initial must be finite and > 0");
  require(o.rho_growth >= 1.0, "rho_growth must be >= 1");
  require(o.rho_max >= o.rho_initial, "rho_max must be >= rho_initial");
  require(o.max_outer_iterations >= 1, "max_outer_iterations must be >= 1");
  require(o.position_tolerance_m > 0.0, "position_tolerance_m must be > 0");
  require(o.orientation_tolerance_rad > 0.0, "orientation_tolerance_rad must be > 0");
}

bool AlmConverged(const AugmentedLagrangianOptions& options, const Vector6d& r) {
  return r.head<3>().norm() <= options.position_tolerance_m &&
         r.tail<3>().norm() <= options.orientation_tolerance_rad;
}

void AlmUpdate(const AugmentedLagrangianOptions& options, const Vector6d& r, Vector6d* lambda,
               double* rho) {
  *lambda += *rho * r;
  *rho = std::min(*rho * options.rho_growth, options.rho_max);
}

}  // namespace topay
