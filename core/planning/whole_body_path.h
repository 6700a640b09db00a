#pragma once

#include <vector>

#include "core/robot/whole_body_state.h"

namespace topay {

/// A whole-body path from the front end (paper Algorithm 1, one element of P): a sequence of
/// states in SE(2) x R^N, each tagged with the time at which a trapezoidal-free, limit-respecting
/// motion could reach it (used to warm-start the optimizer's piece durations).
struct WholeBodyPath {
  std::vector<WholeBodyState> states;
  std::vector<double> times_s;      ///< Same size as states, times_s[0] = 0, increasing.
  double cost = 0.0;                ///< The RRT* path cost (see core/planning/arm_rrt_star.h).
  int base_path_index = -1;         ///< Index into the front end's base paths.
  int homotopy_class = -1;          ///< Homotopy class of that base path.
};

}  // namespace topay
