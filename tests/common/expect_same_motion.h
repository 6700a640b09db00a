#pragma once

// Test helper: two trajectory samples agree in position (x, y, yaw, q) and in the rates a C2
// join must carry (v, a, omega, beta, qd, qdd): where a replanned or stopping trajectory
// starts against the trajectory it joins.

#include <gtest/gtest.h>

#include "core/trajectory/trajectory_sample.h"

namespace topay::testing {

inline void ExpectSameMotion(const TrajectorySample& a, const TrajectorySample& b,
                             double position_tolerance, double rate_tolerance) {
  EXPECT_NEAR(b.state.x_m, a.state.x_m, position_tolerance);
  EXPECT_NEAR(b.state.y_m, a.state.y_m, position_tolerance);
  EXPECT_NEAR(b.state.yaw_rad, a.state.yaw_rad, position_tolerance);
  EXPECT_NEAR(b.v_mps, a.v_mps, rate_tolerance);
  EXPECT_NEAR(b.a_mps2, a.a_mps2, rate_tolerance);
  EXPECT_NEAR(b.omega_radps, a.omega_radps, rate_tolerance);
  EXPECT_NEAR(b.beta_radps2, a.beta_radps2, rate_tolerance);
  EXPECT_LE((b.state.q_rad - a.state.q_rad).cwiseAbs().maxCoeff(), position_tolerance);
  EXPECT_LE((b.qd_radps - a.qd_radps).cwiseAbs().maxCoeff(), rate_tolerance);
  EXPECT_LE((b.qdd_radps2 - a.qdd_radps2).cwiseAbs().maxCoeff(), rate_tolerance);
}

}  // namespace topay::testing
