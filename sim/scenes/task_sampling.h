#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/common/random.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"
#include "sim/scenes/distance_range.h"

namespace topay {

// Sampling steps shared by the task generators (task_generator.h, tight_task_generator.h).

/// The rectangle (xy, W) generated base positions are drawn from: the scene's bounds shrunk
/// by a wall margin on every side.
struct BaseRegion {
  Eigen::Vector2d min_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d max_m = Eigen::Vector2d::Zero();

  bool Contains(const Eigen::Vector2d& p_m) const {
    return (p_m.array() >= min_m.array()).all() && (p_m.array() <= max_m.array()).all();
  }
};

/// The region of `bounds_W` shrunk by wall_margin_m. Throws std::invalid_argument when the
/// margin leaves no room, or when `range` needs base distances longer than the region's
/// diagonal.
BaseRegion MakeBaseRegion(const Eigen::AlignedBox3d& bounds_W, DistanceRange range,
                          double wall_margin_m);

/// Straight-line distance between the base positions of two states.
double BaseDistance(const WholeBodyState& a, const WholeBodyState& b);

/// Sets state->q_rad (resized to the joint count) to joint values uniform within the limits,
/// each rounded to the 1e-6 grid (quantize.h) and clamped back into its limits.
void DrawUniformArm(const JointLimits& limits, Rng& rng, WholeBodyState* state);

}  // namespace topay
