#include "tools/topay_bench/plan_trajectory_file.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace topay::bench {
namespace {

// x = t (v = 1 m/s), one joint q = 2 t, for 0.025 s.
SampledTrajectory Line() {
  SampledTrajectory trajectory;
  trajectory.duration_s = 0.025;
  trajectory.num_joints = 1;
  trajectory.make_sampler = [] {
    return [](double t_s, TrajectorySample* s) {
      s->t_s = t_s;
      s->state.x_m = t_s;
      s->state.y_m = 0.0;
      s->state.yaw_rad = 0.0;
      s->state.q_rad = Eigen::VectorXd::Constant(1, 2.0 * t_s);
      s->v_mps = 1.0;
    };
  };
  return trajectory;
}

TEST(PlanTrajectoryFileTest, SamplesEveryPeriodAndTheEnd) {
  const std::vector<TrajectorySample> samples = SampleForFile(Line(), 0.01);
  ASSERT_EQ(samples.size(), 4u);  // 0, 0.01, 0.02, 0.025
  EXPECT_DOUBLE_EQ(samples[1].t_s, 0.01);
  EXPECT_DOUBLE_EQ(samples[3].t_s, 0.025);
  EXPECT_DOUBLE_EQ(samples[3].state.x_m, 0.025);
  EXPECT_DOUBLE_EQ(samples[2].state.q_rad(0), 0.04);
  EXPECT_DOUBLE_EQ(samples[0].s_m, 0.0);
  EXPECT_NEAR(samples[3].s_m, 0.025, 1e-15);  // travelled at 1 m/s
}

TEST(PlanTrajectoryFileTest, RejectsABadPeriodOrNoSampler) {
  EXPECT_THROW(SampleForFile(Line(), 0.0), std::invalid_argument);
  EXPECT_THROW(SampleForFile(SampledTrajectory{}, 0.01), std::invalid_argument);
}

TEST(PlanTrajectoryFileTest, AFailedPlanHasMetadataOnly) {
  WholeBodyPlanResult plan;
  plan.status = PlanStatus::kFrontEndFailed;
  plan::TrajectoryMetadata metadata;
  metadata.status = "front_end_failed";
  const plan::TrajectoryFile file = PlanTrajectoryFile(metadata, plan, 0.01);
  EXPECT_FALSE(file.pieces.has_value());
  EXPECT_TRUE(file.samples.empty());
  EXPECT_EQ(file.metadata.status, "front_end_failed");
}

TEST(PlanTrajectoryFileTest, AFlatnessSuccessHasSamplesButNoPieces) {
  WholeBodyPlanResult plan;
  plan.status = PlanStatus::kSuccess;
  plan.sampled = Line();
  const plan::TrajectoryFile file = PlanTrajectoryFile({}, plan, 0.01);
  EXPECT_FALSE(file.pieces.has_value());
  EXPECT_EQ(file.samples.size(), 4u);
}

}  // namespace
}  // namespace topay::bench
