#include "core/optimization/back_end_options.h"

#include <stdexcept>
#include <string>

namespace topay {

void CheckBackEndOptions(const BackEndOptions& o, std::string_view owner) {
  const auto require = [owner](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string(owner) + ": " + what);
  };
  CheckAugmentedLagrangianOptions(o.alm, owner);
  require(o.ee_position_tolerance_m > 0.0, "ee_position_tolerance_m must be > 0");
  require(o.ee_orientation_tolerance_rad > 0.0, "ee_orientation_tolerance_rad must be > 0");
  require(o.time_limit_s > 0.0, "time_limit_s must be > 0 (+infinity: no limit)");
  CheckLbfgsOptions(o.lbfgs);
  CheckWarmStartOptions(o.warm_start);
}

}  // namespace topay
