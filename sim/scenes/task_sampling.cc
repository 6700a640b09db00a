#include "sim/scenes/task_sampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/scenes/quantize.h"

namespace topay {

BaseRegion MakeBaseRegion(const Eigen::AlignedBox3d& bounds_W, DistanceRange range,
                          double wall_margin_m) {
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(wall_margin_m);
  const BaseRegion region{bounds_W.min().head<2>() + margin, bounds_W.max().head<2>() - margin};
  if (!(region.min_m.array() < region.max_m.array()).all()) {
    throw std::invalid_argument("task generator: wall_margin_m leaves no room for the base");
  }
  const double diagonal = (region.max_m - region.min_m).norm();
  if (DistanceRangeBounds(range).min_m > diagonal) {
    throw std::invalid_argument("task generator: range \"" +
                                std::string(DistanceRangeName(range)) +
                                "\" needs base distances the room cannot hold");
  }
  return region;
}

double BaseDistance(const WholeBodyState& a, const WholeBodyState& b) {
  return std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
}

void DrawUniformArm(const JointLimits& limits, Rng& rng, WholeBodyState* state) {
  const Eigen::Index n = limits.q_min_rad.size();
  state->q_rad.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double q = QuantizeMicro(rng.Uniform(limits.q_min_rad(j), limits.q_max_rad(j)));
    state->q_rad(j) = std::clamp(q, limits.q_min_rad(j), limits.q_max_rad(j));
  }
}

}  // namespace topay
