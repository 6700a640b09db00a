#include "core/robot/whole_body_state.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(WholeBodyStateTest, VectorRoundTrip) {
  WholeBodyState state;
  state.x_m = 1.5;
  state.y_m = -2.0;
  state.yaw_rad = 0.3;
  state.q_rad = Eigen::VectorXd::LinSpaced(7, -1.0, 1.0);
  const Eigen::VectorXd z = state.ToVector();
  ASSERT_EQ(z.size(), 10);
  EXPECT_EQ(z(0), 1.5);
  EXPECT_EQ(z(2), 0.3);
  const WholeBodyState back = WholeBodyState::FromVector(z);
  EXPECT_EQ(back.x_m, state.x_m);
  EXPECT_EQ(back.y_m, state.y_m);
  EXPECT_EQ(back.yaw_rad, state.yaw_rad);
  EXPECT_EQ(back.q_rad, state.q_rad);
}

TEST(WholeBodyStateTest, BasePoseIsOnTheGroundRotatedByYaw) {
  WholeBodyState state;
  state.x_m = 2.0;
  state.y_m = 3.0;
  state.yaw_rad = M_PI / 2.0;
  const Eigen::Isometry3d X_WB = state.BasePose();
  const Eigen::Vector3d p_W = X_WB * Eigen::Vector3d(1.0, 0.0, 0.5);
  EXPECT_NEAR(p_W.x(), 2.0, 1e-12);
  EXPECT_NEAR(p_W.y(), 4.0, 1e-12);
  EXPECT_NEAR(p_W.z(), 0.5, 1e-12);
}

TEST(WholeBodyStateTest, DetectsNonFinite) {
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(3);
  EXPECT_TRUE(state.IsFinite());
  state.q_rad(1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(state.IsFinite());
  state.q_rad(1) = 0.0;
  state.yaw_rad = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(state.IsFinite());
}

}  // namespace
}  // namespace topay
