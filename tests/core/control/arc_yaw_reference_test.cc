// The tracker's reference on an arc length-yaw trajectory: its samples are the trajectory's
// (but the jerk), into the tracker's jerk-less samples, on the tracker's clock.

#include "core/control/arc_yaw_reference.h"

#include <gtest/gtest.h>

#include "tests/core/trajectory/straight_drive.h"

namespace topay {
namespace {

TEST(ArcYawReferenceTest, SamplesTheTrajectoryIntoJerklessSamples) {
  const std::shared_ptr<const ArcYawTrajectory> trajectory = test::StraightDrive();
  const TrackerReference reference = MakeArcYawReference(trajectory, 7, 100.0);
  EXPECT_EQ(reference.trajectory_id, 7);
  EXPECT_EQ(reference.start_time_s, 100.0);
  EXPECT_EQ(reference.duration_s, trajectory->duration_s());
  TrajectorySample full = trajectory->MakePoint();
  TrajectorySample sample = MakeTrajectorySample(2);  // what the tracker passes: no jerk
  for (const double t_s : {0.0, 1.3, 4.0, 7.9}) {
    trajectory->Evaluate(t_s, &full);
    reference.sampler(t_s, &sample);
    EXPECT_EQ(sample.jerk.size(), 0);
    EXPECT_EQ(sample.t_s, full.t_s);
    EXPECT_EQ(sample.state.x_m, full.state.x_m);
    EXPECT_EQ(sample.state.y_m, full.state.y_m);
    EXPECT_EQ(sample.state.yaw_rad, full.state.yaw_rad);
    EXPECT_EQ(sample.state.q_rad, full.state.q_rad);
    EXPECT_EQ(sample.s_m, full.s_m);
    EXPECT_EQ(sample.v_mps, full.v_mps);
    EXPECT_EQ(sample.omega_radps, full.omega_radps);
    EXPECT_EQ(sample.a_mps2, full.a_mps2);
    EXPECT_EQ(sample.beta_radps2, full.beta_radps2);
    EXPECT_EQ(sample.qd_radps, full.qd_radps);
    EXPECT_EQ(sample.qdd_radps2, full.qdd_radps2);
  }
  EXPECT_GT(sample.state.x_m, 4.9);  // near the end
}

}  // namespace
}  // namespace topay
