#include "core/planning/base_escape.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/angles.h"

namespace topay {
namespace {

// Unit directions by preference: smallest angle to the base's axis first, forwards first
// (DiscreteSE2 drives forwards only: an exit behind costs a turn in place first).
std::vector<Eigen::Vector2d> PreferredDirections(double heading_rad, int count) {
  struct Direction {
    double off_axis_rad;
    bool forwards;
    Eigen::Vector2d u;
  };
  std::vector<Direction> directions;
  for (int k = 0; k < count; ++k) {
    const double angle = heading_rad + std::numbers::pi + 2.0 * std::numbers::pi * k / count;
    const double from_backwards = std::abs(WrapAngle(angle - heading_rad - std::numbers::pi));
    const double from_forwards = std::abs(WrapAngle(angle - heading_rad));
    directions.push_back({std::min(from_backwards, from_forwards), from_forwards < from_backwards,
                          Eigen::Vector2d(std::cos(angle), std::sin(angle))});
  }
  std::stable_sort(directions.begin(), directions.end(), [](const Direction& a, const Direction& b) {
    if (a.off_axis_rad != b.off_axis_rad) return a.off_axis_rad < b.off_axis_rad - 1e-12;
    return a.forwards && !b.forwards;
  });
  std::vector<Eigen::Vector2d> units;
  for (const Direction& d : directions) units.push_back(d.u);
  return units;
}

bool MoveIsClear(const WholeBodyValidity& validity, const Eigen::Vector2d& a,
                 const Eigen::Vector2d& b, double step_m) {
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step_m)));
  for (int k = 0; k <= steps; ++k) {
    if (!validity.IsBaseValid(a + (b - a) * (static_cast<double>(k) / steps))) return false;
  }
  return true;
}

}  // namespace

void CheckBaseEscapeOptions(const BaseEscapeOptions& o) {
  const auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) throw std::invalid_argument(std::string("BaseEscapeOptions::") + field + " must be " + rule);
  };
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  require(positive(o.max_distance_m), "max_distance_m", "finite and > 0");
  require(positive(o.step_m), "step_m", "finite and > 0");
  require(positive(o.check_step_m), "check_step_m", "finite and > 0");
  require(o.num_directions >= 4, "num_directions", ">= 4");
}

std::optional<Eigen::Vector2d> FindBaseEscape(const BaseFreeSpace& free_space,
                                              const WholeBodyValidity& validity,
                                              const Eigen::Vector2d& p_W, double heading_rad,
                                              const BaseEscapeOptions& options) {
  CheckBaseEscapeOptions(options);
  if (!p_W.allFinite() || !std::isfinite(heading_rad)) return std::nullopt;
  const std::vector<Eigen::Vector2d> directions =
      PreferredDirections(heading_rad, options.num_directions);
  const int rings = static_cast<int>(std::floor(options.max_distance_m / options.step_m + 1e-9));
  for (int ring = 1; ring <= rings; ++ring) {
    const double radius_m = ring * options.step_m;
    for (const Eigen::Vector2d& u : directions) {
      const Eigen::Vector2d exit = p_W + radius_m * u;
      if (!free_space.IsFree(exit)) continue;
      if (MoveIsClear(validity, p_W, exit, options.check_step_m)) return exit;
    }
  }
  return std::nullopt;
}

}  // namespace topay
