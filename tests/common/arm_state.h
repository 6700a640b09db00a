#pragma once

// Test helper: a whole-body state of the TopAY robot with its arm in one clear, bent pose
// (q = 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1 rad) that several planner tests start from.

#include "core/robot/whole_body_state.h"

namespace topay {

/// The base at (x, y, yaw) (m, m, rad), the arm in the tests' bent pose (7 joints).
inline WholeBodyState BentArmState(double x_m, double y_m, double yaw_rad) {
  WholeBodyState state;
  state.x_m = x_m;
  state.y_m = y_m;
  state.yaw_rad = yaw_rad;
  state.q_rad.resize(7);
  state.q_rad << 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1;
  return state;
}

}  // namespace topay
