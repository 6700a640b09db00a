#include "core/planning/arm_dwell.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

void CheckArmDwellOptions(const ArmDwellOptions& o) {
  const auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) throw std::invalid_argument(std::string("ArmDwellOptions::") + field + " must be " + rule);
  };
  require(std::isfinite(o.travel_time_factor) && o.travel_time_factor >= 0.0, "travel_time_factor",
          "finite and >= 0");
  require(std::isfinite(o.min_time_s) && o.min_time_s >= 0.0, "min_time_s", "finite and >= 0");
  require(std::isfinite(o.step_s) && o.step_s > 0.0, "step_s", "finite and > 0");
}

double ArmTimeNeeded(const Eigen::VectorXd& q_start_rad, const Eigen::VectorXd& q_goal_rad,
                     const Eigen::VectorXd& qd_max_radps, const ArmDwellOptions& options) {
  const double travel_s =
      q_start_rad.size() == 0
          ? 0.0
          : ((q_goal_rad - q_start_rad).cwiseAbs().array() / qd_max_radps.array()).maxCoeff();
  return options.travel_time_factor * travel_s + options.min_time_s;
}

double AddArmDwell(const Eigen::VectorXd& q_start_rad, const Eigen::VectorXd& q_goal_rad,
                   const Eigen::VectorXd& qd_max_radps, const ArmDwellOptions& options,
                   DiscreteSE2Path* path) {
  const double missing_s =
      ArmTimeNeeded(q_start_rad, q_goal_rad, qd_max_radps, options) - path->total_time_s();
  if (!(missing_s > 0.0) || path->layers.empty()) return 0.0;
  const int steps = static_cast<int>(std::ceil(missing_s / options.step_s));
  const double step_s = missing_s / steps;
  for (int k = 0; k < steps; ++k) {
    Se2Layer layer = path->layers.back();
    layer.time_s += step_s;
    layer.step_time_s = step_s;
    layer.turn_in_place = true;
    path->layers.push_back(layer);
  }
  return missing_s;
}

}  // namespace topay
