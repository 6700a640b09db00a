#include "core/planning/exact_zones.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

void CheckExactZoneOptions(const ExactZoneOptions& o) {
  const auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) throw std::invalid_argument(std::string("ExactZoneOptions::") + field + " must be " + rule);
  };
  require(std::isfinite(o.radius_m) && o.radius_m >= 0.0, "radius_m", "finite and >= 0");
  require(std::isfinite(o.obstacle_margin_m) && o.obstacle_margin_m >= 0.0, "obstacle_margin_m",
          "finite and >= 0");
  require(std::isfinite(o.self_margin_m), "self_margin_m", "finite");
}

bool ExactZones::Contains(const Eigen::Vector2d& p_WB) const {
  if (checker == nullptr) return false;
  const double r2 = options.radius_m * options.radius_m;
  for (const Eigen::Vector2d& c : centres_W_m) {
    if ((p_WB - c).squaredNorm() <= r2) return true;
  }
  return false;
}

}  // namespace topay
