// The box on the route: ahead of the robot by the drawn arc length, on the path, clear of the
// robot and the room; refused when it would overlap a box, cut the goal off, or stand too near
// the path's end; the re-check after the robot moved on.

#include "sim/scenarios/route_box.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "scenario_robot.h"
#include "tests/common/make_box.h"

namespace topay::test {
namespace {

// A 20 x 20 m room with walls (the reachability proofs count the outside of the bounds as
// free) and nothing else, and a straight path along y = 0 from x = -6 to x = -6 + length_m,
// 2 cm apart; the robot at its start.
Scene EmptyRoom() {
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 1.6));
  for (const double side : {-9.9, 9.9}) {
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(side, 0, 0.5), Eigen::Vector3d(0.2, 20, 1)));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(0, side, 0.5), Eigen::Vector3d(20, 0.2, 1)));
  }
  return scene;
}

RouteQuery StraightRoute(double length_m) {
  RouteQuery route;
  for (double x = 0.0; x <= length_m + 1e-9; x += 0.02) route.path_W_m.emplace_back(-6.0 + x, 0.0);
  route.p_WR_m = route.path_W_m.front();
  return route;
}

OrientedBox Box(double x, double y, double sx, double sy) { return MakeBox({x, y, 0.5}, {sx, sy, 1.0}); }

TEST(RouteBox, AheadOnThePathClearOfTheRobot) {
  const RouteQuery route = StraightRoute(12.0);
  const RouteBoxOptions options;
  Rng rng(4);
  for (int k = 0; k < 5; ++k) {
    const std::optional<RouteBox> placed = PlaceRouteBox(route, EmptyRoom(), TopayKinematics(), options, &rng);
    ASSERT_TRUE(placed.has_value());
    EXPECT_GE(placed->ahead_m, options.ahead_min_m);
    EXPECT_LE(placed->ahead_m, options.ahead_max_m + 0.02);
    EXPECT_NEAR(placed->box.center_W_m.x(), -6.0 + placed->ahead_m, 1e-9);
    EXPECT_EQ(placed->box.center_W_m.y(), 0.0);
    EXPECT_EQ(placed->box.center_W_m.z(), 0.5 * options.height_m);
    EXPECT_GE(placed->box.size_m.x(), options.side_min_m);
    EXPECT_LE(placed->box.size_m.x(), options.side_max_m);
    EXPECT_GE((placed->box.center_W_m.head<2>() - route.p_WR_m).norm(), options.min_robot_distance_m);
  }
}

TEST(RouteBox, RefusedWhenItWouldOverlapTheRoom) {
  Scene room = EmptyRoom();
  room.boxes.push_back(Box(-2.0, 0.5, 4.0, 0.4));  // beside the path over x in [-4, 0]: 0.3 m from y = 0
  RouteBoxOptions options;
  options.side_min_m = options.side_max_m = 0.4;  // the box reaches y = 0.2: 0.1 m from the room's box
  Rng rng(1);
  EXPECT_FALSE(PlaceRouteBox(StraightRoute(12.0), room, TopayKinematics(), options, &rng).has_value());
  options.scene_gap_m = 0.05;
  EXPECT_TRUE(PlaceRouteBox(StraightRoute(12.0), room, TopayKinematics(), options, &rng).has_value());
}

TEST(RouteBox, RefusedWhenItWouldCutTheGoalOff) {
  // A wall across the room at x in [-3.5, -1.5] with a slot |y| < 0.6 the path runs through:
  // open for the robot (0.8 m wide + 2 x 0.15 m), closed by any box in it.
  Scene room = EmptyRoom();
  room.boxes.push_back(Box(-2.5, -5.3, 2.0, 9.4));
  room.boxes.push_back(Box(-2.5, 5.3, 2.0, 9.4));
  RouteBoxOptions options;
  options.scene_gap_m = 0.0;
  options.side_min_m = options.side_max_m = 0.3;
  Rng rng(2);
  EXPECT_FALSE(PlaceRouteBox(StraightRoute(12.0), room, TopayKinematics(), options, &rng).has_value());
  // The same slot 3 m wide: the robot gets round the box.
  room.boxes.resize(room.boxes.size() - 2);
  room.boxes.push_back(Box(-2.5, -6.0, 2.0, 9.0));
  room.boxes.push_back(Box(-2.5, 6.0, 2.0, 9.0));
  EXPECT_TRUE(PlaceRouteBox(StraightRoute(12.0), room, TopayKinematics(), options, &rng).has_value());
}

TEST(RouteBox, RefusedTooNearThePathsEnd) {
  Rng rng(3);
  const RouteBoxOptions options;  // ahead 2.5-3.5 m, 1 m of path beyond the box
  EXPECT_FALSE(PlaceRouteBox(StraightRoute(3.4), EmptyRoom(), TopayKinematics(), options, &rng).has_value());
  EXPECT_TRUE(PlaceRouteBox(StraightRoute(4.6), EmptyRoom(), TopayKinematics(), options, &rng).has_value());
}

TEST(RouteBox, RecheckMeasuresFromWhereTheRobotIsNow) {
  RouteQuery route = StraightRoute(12.0);
  Rng rng(5);
  const RouteBoxOptions options;
  const std::optional<RouteBox> placed = PlaceRouteBox(route, EmptyRoom(), TopayKinematics(), options, &rng);
  ASSERT_TRUE(placed.has_value());
  route.robot_index = 25;  // 0.5 m on
  route.p_WR_m = route.path_W_m[25];
  const std::optional<RouteBox> later = RecheckRouteBox(*placed, route, options);
  ASSERT_TRUE(later.has_value());
  EXPECT_NEAR(later->ahead_m, placed->ahead_m - 0.5, 1e-9);
  route.robot_index = placed->path_index - 90;  // 1.8 m before the box: too near
  route.p_WR_m = route.path_W_m[route.robot_index];
  EXPECT_FALSE(RecheckRouteBox(*placed, route, options).has_value());
}

TEST(RouteBox, BadOptionsThrowNamingTheOption) {
  RouteBoxOptions options;
  options.ahead_max_m = 1.0;  // below ahead_min_m
  try {
    CheckRouteBoxOptions(options);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ahead_max_m"), std::string::npos);
  }
  options = {};
  options.tries = 0;
  EXPECT_THROW(CheckRouteBoxOptions(options), std::invalid_argument);
}

}  // namespace
}  // namespace topay::test
