#include "tools/topay_faults/obstacle_goal.h"

#include <set>
#include <stdexcept>

#include <gtest/gtest.h>

namespace topay::tools {
namespace {

const std::vector<Eigen::Vector3d> kBoxes = {{0.0, 0.0, 0.5}, {1.0, 1.0, 0.2}, {-2.0, 0.5, 0.1}, {20.0, 0.0, 0.5}};

TEST(ObstacleGoalTest, ChoosesAmongTheBoxesNearTheRobot) {
  std::mt19937_64 random(3);
  std::set<double> chosen_x;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d goal = ChooseObstacleGoal(kBoxes, Eigen::Vector2d(0.2, 0.2), 3.0, &random);
    chosen_x.insert(goal.x());
  }
  EXPECT_EQ(chosen_x, (std::set<double>{0.0, 1.0, -2.0}));  // all three near ones, never the far one
}

TEST(ObstacleGoalTest, NoneNearTakesTheNearestAndNoRobotAny) {
  std::mt19937_64 random(3);
  EXPECT_EQ(ChooseObstacleGoal(kBoxes, Eigen::Vector2d(15.0, 0.0), 3.0, &random).x(), 20.0);
  std::set<double> chosen_x;
  for (int i = 0; i < 200; ++i) chosen_x.insert(ChooseObstacleGoal(kBoxes, std::nullopt, 3.0, &random).x());
  EXPECT_EQ(chosen_x.size(), kBoxes.size());
  EXPECT_THROW(ChooseObstacleGoal({}, std::nullopt, 3.0, &random), std::invalid_argument);
}

}  // namespace
}  // namespace topay::tools
