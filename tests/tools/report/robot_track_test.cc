// The driven path and the base position nearest in time.

#include "tools/report/robot_track.h"

#include <gtest/gtest.h>

namespace topay::report {
namespace {

msgs::RobotStateEstimate State(std::int64_t utime, double x_m, double y_m) {
  msgs::RobotStateEstimate s;
  s.utime = utime;
  s.state.x_m = x_m;
  s.state.y_m = y_m;
  return s;
}

TEST(RobotTrack, NearestStateInTime) {
  const std::vector<msgs::RobotStateEstimate> states = {State(100, 0, 0), State(200, 1, 0), State(300, 2, 5)};
  EXPECT_FALSE(BasePositionAt({}, 100).has_value());
  EXPECT_EQ(*BasePositionAt(states, 0), Eigen::Vector2d(0, 0));    // before the first
  EXPECT_EQ(*BasePositionAt(states, 140), Eigen::Vector2d(0, 0));
  EXPECT_EQ(*BasePositionAt(states, 160), Eigen::Vector2d(1, 0));
  EXPECT_EQ(*BasePositionAt(states, 260), Eigen::Vector2d(2, 5));
  EXPECT_EQ(*BasePositionAt(states, 999), Eigen::Vector2d(2, 5));  // after the last
  const std::vector<Eigen::Vector2d> path = DrivenPath(states);
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path[2], Eigen::Vector2d(2, 5));
}

}  // namespace
}  // namespace topay::report
