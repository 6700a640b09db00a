// The pick-and-place scenario: for several seeds, both goals are exactly clear by the margin,
// above a table top, reachable through passages the sensed map keeps open, and the drop-off is
// across the room; the room is topay-sim's; the same seed gives the same scenario.

#include "sim/scenarios/pick_place_scenario.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/collision/scene_clearance.h"
#include "scenario_robot.h"
#include "sim/scenarios/sensed_reachability.h"
#include "sim/scenarios/unseen_room.h"
#include "sim/scenes/scene_json.h"

namespace topay::test {
namespace {

class PickPlaceScenarioSeeds : public testing::TestWithParam<std::uint64_t> {};

TEST_P(PickPlaceScenarioSeeds, GoalsAreClearOnTableTopsReachableAndApart) {
  const PickPlaceScenarioOptions options;
  const PickPlaceScenario& s = DefaultScenario(GetParam());
  const Kinematics& kinematics = TopayKinematics();
  const SceneClearanceChecker checker(kinematics, s.room.scene);
  const Eigen::Vector2d p_pickup(s.pickup.state.x_m, s.pickup.state.y_m);
  const Eigen::Vector2d p_dropoff(s.dropoff.state.x_m, s.dropoff.state.y_m);
  for (const TableTopGoal* goal : {&s.pickup, &s.dropoff}) {
    const SceneClearance clearance = checker.Compute(goal->state);
    EXPECT_TRUE(clearance.IsCollisionFree(options.obstacle_clearance_m, 0.0))
        << "base " << clearance.base_m << " m, arm " << clearance.spheres_m << " m, self " << clearance.self_m;
    EXPECT_DOUBLE_EQ(goal->clearance_m, clearance.obstacle_m());
    ASSERT_EQ(s.room.roles.at(goal->table_top), BoxRole::kTableTop);
    EXPECT_TRUE(AboveTableTop(s.room.scene.boxes[goal->table_top], goal->X_WE.translation(), options));
    EXPECT_TRUE(goal->X_WE.isApprox(kinematics.EndEffectorPose(goal->state), 1e-12));
  }
  EXPECT_NE(s.pickup.table_top, s.dropoff.table_top);
  EXPECT_GE(p_pickup.norm(), options.pickup_distance_min_m);
  EXPECT_GE((p_dropoff - p_pickup).norm(), options.dropoff_distance_min_m);
  EXPECT_TRUE(SensedReachableRegion(s.room.scene, kinematics, s.p_W_start_m).Reaches(p_pickup));
  EXPECT_TRUE(SensedReachableRegion(s.room.scene, kinematics, p_pickup).Reaches(p_dropoff));
  // The tool (E's z axis) is tilted within the options' pitch range (the IK's 0.01 rad).
  for (const TableTopGoal* goal : {&s.pickup, &s.dropoff}) {
    const double pitch = -std::asin(goal->X_WE.rotation().col(2).z());
    EXPECT_GE(pitch, options.tool_pitch_min_rad - 0.01);
    EXPECT_LE(pitch, options.tool_pitch_max_rad + 0.01);
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, PickPlaceScenarioSeeds, testing::Values(1, 2, 4, 5));

TEST(PickPlaceScenario, RoomIsTheUnseenTablesRoomOfTheSeed) {
  EXPECT_EQ(SceneToJson(DefaultScenario(1).room.scene), SceneToJson(UnseenTablesRoom(1, 1.2).scene));
}

TEST(PickPlaceScenario, SameSeedSameScenario) {
  const PickPlaceScenario again = MakePickPlaceScenario({}, 2, TopayKinematics());
  const PickPlaceScenario& first = DefaultScenario(2);
  EXPECT_EQ(again.pickup.table_top, first.pickup.table_top);
  EXPECT_EQ(again.dropoff.table_top, first.dropoff.table_top);
  EXPECT_EQ(again.pickup.state.q_rad, first.pickup.state.q_rad);
  EXPECT_EQ(again.dropoff.state.x_m, first.dropoff.state.x_m);
  EXPECT_EQ(again.dropoff.state.q_rad, first.dropoff.state.q_rad);
  EXPECT_NE(DefaultScenario(1).pickup.state.x_m, first.pickup.state.x_m);
}

TEST(PickPlaceScenario, ImpossibleOptionsThrowNamingTheSeed) {
  PickPlaceScenarioOptions options;
  options.dropoff_distance_min_m = 40.0;  // beyond the 20 x 20 m room
  options.max_targets = 5;
  options.max_pickups = 1;
  try {
    MakePickPlaceScenario(options, 7, TopayKinematics());
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("seed 7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::test
