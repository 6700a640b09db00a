#include "procs/planner/goal_screen.h"

#include <gtest/gtest.h>

#include "procs/msgs/map_codec.h"
#include "tests/procs/planner/planner_test_support.h"

namespace topay::planner {
namespace {

msgs::PlanGoal GoalAt(const Eigen::Vector3d& p_WE) {
  msgs::PlanGoal goal;
  goal.goal_id = 1;
  goal.X_WE.translation() = p_WE;
  return goal;
}

TEST(GoalScreenTest, RefusesTargetsOutsideTheMapOutOfReachOrInsideAnObstacle) {
  MapIntake map(UnknownVoxelPolicy::kFree);
  msgs::MapAcceptResult result;
  const GridGeometry3 g = testing::RoomGeometry();
  map.Accept(msgs::EncodeFullMap(g, testing::StatesOf(g, testing::RoomBoxes()), 1, 1), &result);
  const ReachHeights reach{0.1, 1.5};
  const GoalCheckOptions options;
  EXPECT_EQ(ScreenGoal(GoalAt({2.0, 2.0, 0.8}), map, reach, options), "");
  EXPECT_NE(ScreenGoal(GoalAt({2.0, 2.0, 1.8}), map, reach, options).find("outside the arm's reach"), std::string::npos);
  EXPECT_NE(ScreenGoal(GoalAt({6.0, 2.0, 0.8}), map, reach, options).find("outside the map"), std::string::npos);
  EXPECT_NE(ScreenGoal(GoalAt({0.0, 0.0, 0.5}), map, reach, options).find("inside an obstacle"), std::string::npos);
  // Near the table top: only with a clearance.
  EXPECT_EQ(ScreenGoal(GoalAt({0.0, 0.0, 0.8}), map, reach, options), "");
  GoalCheckOptions clearance;
  clearance.target_clearance_m = 0.1;
  EXPECT_NE(ScreenGoal(GoalAt({0.0, 0.0, 0.8}), map, reach, clearance).find("inside an obstacle"), std::string::npos);
}

// A box seen only from outside (its rim occupied, its inside unknown): a target at its centre is
// inside an obstacle (finding 35), unless the check is off; one above it is not.
TEST(GoalScreenTest, RefusesATargetInsideABodySeenOnlyFromOutside) {
  MapIntake map(UnknownVoxelPolicy::kFree);
  msgs::MapAcceptResult result;
  const GridGeometry3 g = testing::RoomGeometry();
  map.Accept(msgs::EncodeFullMap(g, testing::StatesOf(g, testing::RoomBoxes()), 1, 1), &result);
  map.Accept(msgs::EncodeMapDelta(g, testing::UnseenBody(g, MakeBox({-2.0, 1.5, 0.4}, {0.5, 0.6, 0.8})), 2, 2),
             &result);
  ASSERT_EQ(result.outcome, msgs::MapUpdateOutcome::kDeltaApplied) << result.reason;
  const ReachHeights reach{0.1, 1.5};
  GoalCheckOptions options;
  const std::string reason = ScreenGoal(GoalAt({-2.0, 1.5, 0.4}), map, reach, options);
  EXPECT_NE(reason.find("a body seen only from outside"), std::string::npos) << reason;
  EXPECT_EQ(ScreenTargetInMap({-2.0, 1.5, 0.4}, map, options), reason);
  EXPECT_EQ(ScreenGoal(GoalAt({-2.0, 1.5, 0.9}), map, reach, options), "");  // above its top
  options.unseen_pocket_reach_m = 0.0;
  EXPECT_EQ(ScreenGoal(GoalAt({-2.0, 1.5, 0.4}), map, reach, options), "");
  options.unseen_pocket_reach_m = 0.2;  // a body wider than the reach is not recognised
  EXPECT_EQ(ScreenGoal(GoalAt({-2.0, 1.5, 0.4}), map, reach, options), "");
}

TEST(GoalScreenTest, WithoutAMapOnlyTheReachIsChecked) {
  const MapIntake map(UnknownVoxelPolicy::kFree);
  EXPECT_EQ(ScreenGoal(GoalAt({60.0, 2.0, 0.8}), map, {0.1, 1.5}, {}), "");
  EXPECT_NE(ScreenGoal(GoalAt({6.0, 2.0, -0.5}), map, {0.1, 1.5}, {}), "");
}

}  // namespace
}  // namespace topay::planner
