#include "core/trajectory/arc_yaw_sampling.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

constexpr int kJoints = 7;
constexpr int kPieces = 3;

class SampleArcYawTest : public ::testing::Test {
 protected:
  SampleArcYawTest() : rng_(5), trajectory_(kJoints, kPieces, {}) {
    const testing::MincoInputs in = testing::RandomMincoInputs(kJoints + 2, kPieces, &rng_);
    trajectory_.Update(Eigen::Vector2d(1.0, -2.0), in.head, in.tail, in.waypoints, in.durations);
  }

  Rng rng_;
  ArcYawTrajectory trajectory_;
};

TEST_F(SampleArcYawTest, CopiesEveryQuantityOfEvaluate) {
  const SampledTrajectory sampled = SampleArcYaw(trajectory_);
  EXPECT_EQ(sampled.duration_s, trajectory_.duration_s());
  EXPECT_EQ(sampled.num_joints, kJoints);
  const TrajectorySampler sampler = sampled.make_sampler();
  TrajectorySample sample = MakeTrajectorySample(kJoints);
  TrajectorySample point = trajectory_.MakePoint();
  for (int trial = 0; trial < 30; ++trial) {
    const double t = trial == 0 ? trajectory_.duration_s()
                                : rng_.Uniform(0.0, trajectory_.duration_s());
    sampler(t, &sample);
    trajectory_.Evaluate(t, &point);
    EXPECT_EQ(sample.t_s, point.t_s);
    EXPECT_EQ(sample.state.x_m, point.state.x_m);
    EXPECT_EQ(sample.state.y_m, point.state.y_m);
    EXPECT_EQ(sample.state.yaw_rad, point.state.yaw_rad);
    EXPECT_EQ(sample.state.q_rad, point.state.q_rad);
    EXPECT_EQ(sample.s_m, point.s_m);
    EXPECT_EQ(sample.v_mps, point.v_mps);
    EXPECT_EQ(sample.omega_radps, point.omega_radps);
    EXPECT_EQ(sample.a_mps2, point.a_mps2);
    EXPECT_EQ(sample.beta_radps2, point.beta_radps2);
    EXPECT_EQ(sample.qd_radps, point.qd_radps);
    EXPECT_EQ(sample.qdd_radps2, point.qdd_radps2);
  }
}

TEST_F(SampleArcYawTest, SamplersAreIndependentAndDoNotAllocatePerSample) {
  const SampledTrajectory sampled = SampleArcYaw(trajectory_);
  const TrajectorySampler first = sampled.make_sampler();
  const TrajectorySampler second = sampled.make_sampler();
  TrajectorySample a = MakeTrajectorySample(kJoints), b = MakeTrajectorySample(kJoints);
  // Interleaved calls at different times do not disturb each other.
  first(0.3, &a);
  second(1.7, &b);
  TrajectorySample again = MakeTrajectorySample(kJoints);
  first(0.3, &again);
  EXPECT_EQ(a.state.q_rad, again.state.q_rad);
  EXPECT_NE(a.state.q_rad, b.state.q_rad);
  testing::AllocationCounter counter;
  for (int k = 0; k < 100; ++k) first(0.01 * k, &a);
  EXPECT_EQ(counter.count(), 0);
}

TEST(SampleArcYawErrorsTest, RejectsATrajectoryWithoutUpdate) {
  const ArcYawTrajectory trajectory(kJoints, kPieces, {});
  EXPECT_THROW(SampleArcYaw(trajectory), std::invalid_argument);
}

}  // namespace
}  // namespace topay
