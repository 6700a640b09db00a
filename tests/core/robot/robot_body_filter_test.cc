#include "core/robot/robot_body_filter.h"

#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

class RobotBodyFilterTest : public ::testing::Test {
 protected:
  RobotBodyFilterTest()
      : model_(topay::testing::LoadTopayModel()), kinematics_(model_),
        cache_(kinematics_.MakeCache()) {
    state_.x_m = 2.0;
    state_.y_m = -1.0;
    state_.yaw_rad = 0.7;
    state_.q_rad = Eigen::VectorXd::Zero(model_.num_joints());
    kinematics_.Update(state_, &cache_);
  }

  RobotModel model_;
  Kinematics kinematics_;
  KinematicsCache cache_;
  WholeBodyState state_;
};

TEST_F(RobotBodyFilterTest, SpheresAndTheBaseCylinderAreInsideWithTheMargin) {
  RobotBodyFilter body(0.05);
  body.Update(model_, cache_);
  for (std::size_t s = 0; s < model_.spheres.size(); ++s) {
    const Eigen::Vector3d c = cache_.p_WS[s];
    const double reach = model_.spheres[s].radius_m + 0.05;
    EXPECT_TRUE(body.Contains(c.cast<float>()));
    // Just inside the inflated sphere, straight up or sideways.
    EXPECT_TRUE(body.Contains((c + Eigen::Vector3d(0, 0, reach - 1e-3)).cast<float>()));
    EXPECT_TRUE(body.Contains((c + Eigen::Vector3d(reach - 1e-3, 0, 0)).cast<float>()));
  }
  const Eigen::Vector3d axis(2.0, -1.0, 0.0);
  const double r = model_.base_cylinder.radius_m, h = model_.base_cylinder.height_m;
  EXPECT_TRUE(body.Contains((axis + Eigen::Vector3d(r + 0.049, 0, 0.1)).cast<float>()));
  EXPECT_TRUE(body.Contains((axis + Eigen::Vector3d(0, -r - 0.049, -0.049)).cast<float>()));
  EXPECT_TRUE(body.Contains((axis + Eigen::Vector3d(0.3, 0, h + 0.049)).cast<float>()));
  EXPECT_FALSE(body.Contains((axis + Eigen::Vector3d(r + 0.051, 0, 0.1)).cast<float>()));
  EXPECT_FALSE(body.Contains((axis + Eigen::Vector3d(0, 0, -0.06)).cast<float>()));
  EXPECT_FALSE(body.Contains(Eigen::Vector3f(10, 10, 0.5)));
  // The box holds the inflated body and excludes far points.
  EXPECT_TRUE(body.bounds_W().contains(axis.cast<float>()));
  EXPECT_LT(body.bounds_W().sizes().head<2>().maxCoeff(), 3.0f);
}

TEST_F(RobotBodyFilterTest, RemoveFromKeepsTheOthersInOrder) {
  RobotBodyFilter body(0.05);
  body.Update(model_, cache_);
  std::vector<Eigen::Vector3f> points = {
      {5, 5, 1}, cache_.p_WS[0].cast<float>(), {-3, 0, 0.5}, Eigen::Vector3f(2, -1, 0.1)};
  EXPECT_EQ(body.RemoveFrom(&points), 2);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0], Eigen::Vector3f(5, 5, 1));
  EXPECT_EQ(points[1], Eigen::Vector3f(-3, 0, 0.5));
}

TEST_F(RobotBodyFilterTest, TheBodyFollowsTheState) {
  RobotBodyFilter body(0.0);
  body.Update(model_, cache_);
  const Eigen::Vector3f p_W = cache_.p_WS.back().cast<float>();  // the top sphere
  EXPECT_TRUE(body.Contains(p_W));
  state_.x_m += 3.0;
  kinematics_.Update(state_, &cache_);
  body.Update(model_, cache_);
  EXPECT_FALSE(body.Contains(p_W));
}

TEST_F(RobotBodyFilterTest, BadMarginsAreRejected) {
  EXPECT_THROW(RobotBodyFilter(-0.01), std::invalid_argument);
  EXPECT_THROW(RobotBodyFilter(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace topay
