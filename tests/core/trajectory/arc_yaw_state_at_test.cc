#include "core/trajectory/arc_yaw_state_at.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/common/expect_same_motion.h"

#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

constexpr int kJoints = 7;

ArcYawTrajectory RandomTrajectory(Rng* rng, int pieces) {
  const testing::MincoInputs in = testing::RandomMincoInputs(kJoints + 2, pieces, rng);
  ArcYawTrajectory trajectory(kJoints, pieces, ArcYawTrajectory::Options());
  trajectory.Update(Eigen::Vector2d(0.3, -1.2), in.head, in.tail, in.waypoints, in.durations);
  return trajectory;
}

TEST(ArcYawStateAtTest, IsTheTrajectorysStateAndRates) {
  Rng rng(7);
  const ArcYawTrajectory trajectory = RandomTrajectory(&rng, 4);
  TrajectorySample sample = trajectory.MakePoint();
  for (double f : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const double t = f * trajectory.duration_s();
    const MovingState at = ArcYawStateAt(trajectory, t);
    trajectory.Evaluate(t, &sample);
    EXPECT_EQ(at.state.x_m, sample.state.x_m);
    EXPECT_EQ(at.state.y_m, sample.state.y_m);
    EXPECT_EQ(at.state.yaw_rad, sample.state.yaw_rad);
    EXPECT_EQ(at.state.q_rad, sample.state.q_rad);
    EXPECT_EQ(at.rates.v_mps, sample.v_mps);
    EXPECT_EQ(at.rates.omega_radps, sample.omega_radps);
    EXPECT_EQ(at.rates.a_mps2, sample.a_mps2);
    EXPECT_EQ(at.rates.beta_radps2, sample.beta_radps2);
    EXPECT_EQ(at.rates.qd_radps, sample.qd_radps);
    EXPECT_EQ(at.rates.qdd_radps2, sample.qdd_radps2);
  }
  EXPECT_THROW(ArcYawStateAt(trajectory, std::nan("")), std::invalid_argument);
}

// A trajectory whose head is StateAt(t0) (s reset to 0) joins the first one C2 at t0: s',
// s'', yaw, yaw', yaw'', q, q', q'' and, from p0 = (x, y)(t0), the base position.
TEST(ArcYawStateAtTest, AHeadFromStateAtJoinsC2) {
  Rng rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const ArcYawTrajectory first = RandomTrajectory(&rng, 3);
    const double t0 = rng.Uniform(0.0, first.duration_s());
    const MovingState at = ArcYawStateAt(first, t0);
    testing::MincoInputs next = testing::RandomMincoInputs(kJoints + 2, 3, &rng);
    next.head.col(0) << 0.0, at.state.yaw_rad, at.state.q_rad;
    next.head.col(1) << at.rates.v_mps, at.rates.omega_radps, at.rates.qd_radps;
    next.head.col(2) << at.rates.a_mps2, at.rates.beta_radps2, at.rates.qdd_radps2;
    ArcYawTrajectory second(kJoints, 3, ArcYawTrajectory::Options());
    second.Update(Eigen::Vector2d(at.state.x_m, at.state.y_m), next.head, next.tail,
                  next.waypoints, next.durations);
    TrajectorySample a = first.MakePoint(), b = second.MakePoint();
    first.Evaluate(t0, &a);
    second.Evaluate(0.0, &b);
    EXPECT_NEAR(b.state.x_m, a.state.x_m, 1e-12);
    EXPECT_NEAR(b.state.y_m, a.state.y_m, 1e-12);
    testing::ExpectSameMotion(a, b, 1e-9, 1e-9);
  }
}

}  // namespace
}  // namespace topay
