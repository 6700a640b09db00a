#include "core/trajectory/trajectory_sample.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(TrajectorySampleTest, MakeSizesEveryJointVectorWithZeros) {
  const TrajectorySample sample = MakeTrajectorySample(7);
  EXPECT_EQ(sample.state.num_joints(), 7);
  EXPECT_EQ(sample.qd_radps.size(), 7);
  EXPECT_EQ(sample.qdd_radps2.size(), 7);
  EXPECT_TRUE(sample.state.q_rad.isZero());
  EXPECT_TRUE(sample.qd_radps.isZero());
  EXPECT_TRUE(sample.qdd_radps2.isZero());
  EXPECT_EQ(sample.v_mps, 0.0);
  EXPECT_EQ(sample.s_m, 0.0);
  EXPECT_EQ(sample.jerk.size(), 0);  // arc length-yaw only (ArcYawTrajectory::MakePoint)
  EXPECT_EQ(MakeTrajectorySample(0).qd_radps.size(), 0);
  EXPECT_THROW(MakeTrajectorySample(-1), std::invalid_argument);
}

}  // namespace
}  // namespace topay
