// The final projection: every input it returns satisfies every limit, it is the identity on
// feasible inputs, and it is the nearest feasible point (no worse than the box clamp).

#include "core/control/command_projection.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::kJoints;
using testing::TopayLimits;

bool BaseFeasible(const Eigen::Vector2d& u, const Eigen::Vector2d& prev, double dt,
                  const TrackerLimits& limits) {
  const double tol = 1e-12;
  return std::abs(u(0)) <= limits.base.v_max_mps + tol &&
         std::abs(u(1)) <= limits.base.omega_max_radps + tol &&
         std::abs(u(0) - prev(0)) <= limits.base.a_max_mps2 * dt + tol &&
         std::abs(u(1) - prev(1)) <= limits.base.beta_max_radps2 * dt + tol &&
         std::abs(u(0)) / limits.base.v_max_mps + std::abs(u(1)) / limits.base.omega_max_radps <=
             1.0 + 1e-9;
}

// A feasible previous input: uniform in the diamond.
Eigen::Vector2d FeasiblePrevious(Rng* rng, const TrackerLimits& limits) {
  for (;;) {
    const Eigen::Vector2d u(rng->Uniform(-1, 1) * limits.base.v_max_mps,
                            rng->Uniform(-1, 1) * limits.base.omega_max_radps);
    if (std::abs(u(0)) / limits.base.v_max_mps + std::abs(u(1)) / limits.base.omega_max_radps <= 1.0) {
      return u;
    }
  }
}

TEST(CommandProjectionTest, EveryProjectedBaseInputIsFeasible) {
  const TrackerLimits limits = TopayLimits();
  Rng rng(11);
  int moved_onto_diamond = 0;
  for (int i = 0; i < 20000; ++i) {
    const double dt = i % 2 ? 0.02 : 0.3;  // small and large rate windows
    const Eigen::Vector2d prev = FeasiblePrevious(&rng, limits);
    const Eigen::Vector2d u(rng.Uniform(-3, 3), rng.Uniform(-3, 3));
    const Eigen::Vector2d p = ProjectBaseInput(u, prev, dt, limits);
    ASSERT_TRUE(BaseFeasible(p, prev, dt, limits)) << "u " << u.transpose() << " prev "
                                                   << prev.transpose() << " p " << p.transpose();
    moved_onto_diamond += std::abs(std::abs(p(0)) / limits.base.v_max_mps +
                                   std::abs(p(1)) / limits.base.omega_max_radps - 1.0) < 1e-9;
    // Nearest: no feasible random point of the rate box is closer to u.
    if (i % 100 == 0) {
      for (int k = 0; k < 200; ++k) {
        const Eigen::Vector2d q(prev(0) + rng.Uniform(-1, 1) * limits.base.a_max_mps2 * dt,
                                prev(1) + rng.Uniform(-1, 1) * limits.base.beta_max_radps2 * dt);
        if (BaseFeasible(q, prev, dt, limits)) {
          ASSERT_GE((q - u).norm(), (p - u).norm() - 1e-9);
        }
      }
    }
  }
  EXPECT_GT(moved_onto_diamond, 100);  // the coupled bound was exercised
}

TEST(CommandProjectionTest, FeasibleInputsAreLeftAlone) {
  const TrackerLimits limits = TopayLimits();
  const Eigen::Vector2d prev(0.5, 0.2);
  const Eigen::Vector2d u(0.51, 0.19);
  EXPECT_EQ(ProjectBaseInput(u, prev, 0.02, limits), u);
  EXPECT_EQ(ProjectJointVelocity(1.0, 1.05, 0.02, 2.35, 6.28), 1.0);
}

TEST(CommandProjectionTest, OnTheDiamondItSlidesAlongTheFace) {
  // From a point on the diamond, asking for more turn and less speed moves along the face
  // (a projection that only moved towards the previous input would stay put).
  const TrackerLimits limits = TopayLimits();
  const Eigen::Vector2d prev(0.6, 0.36);  // 0.6 + 0.4 = 1
  const Eigen::Vector2d p = ProjectBaseInput(Eigen::Vector2d(0.0, 0.9), prev, 0.02, limits);
  EXPECT_LT(p(0), prev(0) - 1e-3);
  EXPECT_GT(p(1), prev(1) + 1e-3);
  EXPECT_TRUE(BaseFeasible(p, prev, 0.02, limits));
}

TEST(CommandProjectionTest, InfeasiblePreviousInputGivesLimitsPrecedence) {
  const TrackerLimits limits = TopayLimits();
  const Eigen::Vector2d p = ProjectBaseInput(Eigen::Vector2d(3, 3), Eigen::Vector2d(5, 5), 0.02, limits);
  EXPECT_LE(std::abs(p(0)) / limits.base.v_max_mps + std::abs(p(1)) / limits.base.omega_max_radps,
            1.0 + 1e-12);
  EXPECT_EQ(ProjectJointVelocity(9.0, 9.0, 0.02, 2.35, 6.28), 2.35);
}

TEST(CommandProjectionTest, SequencesAreChainedFromTheLastCommand) {
  const TrackerLimits limits = TopayLimits();
  Rng rng(2);
  ControlCommand last = ControlCommand::Zero(kJoints);
  last.v_mps = 0.4;
  last.qd_radps.setConstant(1.0);
  InputSequence inputs = InputSequence::Zero(25, kJoints);
  for (int k = 0; k < 25; ++k) {
    inputs.u_base.col(k) << rng.Uniform(-4, 4), rng.Uniform(-4, 4);
    for (int j = 0; j < kJoints; ++j) inputs.qd_radps(j, k) = rng.Uniform(-8, 8);
  }
  EXPECT_GT(WorstInputLimitRatio(last, 0.02, 0.04, limits, inputs), 1.0);
  const int moved = ProjectInputSequence(last, 0.02, 0.04, limits, &inputs);
  EXPECT_GT(moved, 0);
  EXPECT_LE(WorstInputLimitRatio(last, 0.02, 0.04, limits, inputs), 1.0 + 1e-9);
  EXPECT_EQ(ProjectInputSequence(last, 0.02, 0.04, limits, &inputs), 0);  // idempotent
}

}  // namespace
}  // namespace topay
