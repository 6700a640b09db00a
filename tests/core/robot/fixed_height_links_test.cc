#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <string>

#include "core/robot/fixed_height_links.h"
#include "core/robot/kinematics.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

using testing::LoadTopayModel;
using testing::RandomState;

// The TopAY robot: the base's fixed links and link1 (the shoulder's yaw joint) keep one
// height; link2 onwards hang from the horizontal shoulder pitch axis.
TEST(FixedHeightLinks, OnTheTopayRobotTheFixedLinksAndTheShoulderYawLinkAreLevel) {
  const RobotModel model = LoadTopayModel();
  const std::vector<bool> fixed = FixedHeightLinks(model);
  ASSERT_EQ(fixed.size(), model.links.size());
  const std::vector<std::string> level = {"base_link", "chassis", "arm_base_link", "link1"};
  for (std::size_t l = 0; l < model.links.size(); ++l) {
    const bool expected = std::find(level.begin(), level.end(), model.links[l].name) != level.end();
    EXPECT_EQ(fixed[l], expected) << model.links[l].name;
  }
}

// What the flag promises, checked on random states: the spheres of a fixed-height link keep
// their height. The converse need not hold (a sphere centred on a horizontal joint axis, as
// sphere 2 on the shoulder pitch axis, keeps its height too), but the tool's spheres move.
TEST(FixedHeightLinks, SpheresOfLevelLinksKeepTheirHeight) {
  const RobotModel model = LoadTopayModel();
  const Kinematics kinematics(model);
  const std::vector<bool> fixed = FixedHeightLinks(model);
  KinematicsCache cache = kinematics.MakeCache();
  const int num_spheres = static_cast<int>(model.spheres.size());
  Eigen::VectorXd lowest = Eigen::VectorXd::Constant(num_spheres, 1e9);
  Eigen::VectorXd highest = Eigen::VectorXd::Constant(num_spheres, -1e9);
  Rng rng(7);
  for (int i = 0; i < 200; ++i) {
    kinematics.Update(RandomState(model, &rng), &cache);
    for (int s = 0; s < num_spheres; ++s) {
      lowest(s) = std::min(lowest(s), cache.p_WS[s].z());
      highest(s) = std::max(highest(s), cache.p_WS[s].z());
    }
  }
  for (int s = 0; s < num_spheres; ++s) {
    const double span_m = highest(s) - lowest(s);
    if (fixed[static_cast<std::size_t>(model.spheres[s].link)]) {
      EXPECT_LT(span_m, 1e-9) << "sphere " << s;
    }
  }
  EXPECT_TRUE(fixed[static_cast<std::size_t>(model.spheres[0].link)]);
  EXPECT_GT(highest(11) - lowest(11), 0.3);
}

// A tilted joint frame, a horizontal revolute axis or a prismatic joint breaks the chain for
// the link and everything below it.
TEST(FixedHeightLinks, TiltedFramesHorizontalAxesAndPrismaticJointsDisqualify) {
  RobotModel model;
  const auto add = [&](int parent, JointType type, const Eigen::Vector3d& axis_J,
                       const Eigen::Isometry3d& X_PJ) {
    Link link;
    link.name = "l" + std::to_string(model.links.size());
    link.parent = parent;
    link.joint_type = type;
    link.axis_J = axis_J;
    link.X_PJ = X_PJ;
    model.links.push_back(link);
  };
  Eigen::Isometry3d up = Eigen::Isometry3d::Identity();
  up.translation() = Eigen::Vector3d(0.1, 0.0, 0.3);
  Eigen::Isometry3d flipped = up;
  flipped.linear() = Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  Eigen::Isometry3d tilted = up;
  tilted.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  add(-1, JointType::kFixed, Eigen::Vector3d::UnitZ(), up);                 // 0: level
  add(0, JointType::kRevolute, -Eigen::Vector3d::UnitZ(), flipped);         // 1: level
  add(1, JointType::kRevolute, Eigen::Vector3d::UnitX(), up);               // 2: no
  add(2, JointType::kFixed, Eigen::Vector3d::UnitZ(), up);                  // 3: no (parent)
  add(1, JointType::kFixed, Eigen::Vector3d::UnitZ(), tilted);              // 4: no
  add(1, JointType::kPrismatic, Eigen::Vector3d::UnitX(), up);              // 5: no
  const std::vector<bool> fixed = FixedHeightLinks(model);
  EXPECT_EQ(fixed, (std::vector<bool>{true, true, false, false, false, false}));
}

}  // namespace
}  // namespace topay
