#include "core/planning/base_escape.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/planner_fields.h"
#include "tests/common/tight_scenes.h"

namespace topay {
namespace {

class BaseEscapeTest : public ::testing::Test {
 protected:
  BaseEscapeTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  RobotModel model_;
  Kinematics kinematics_;
};

TEST(BaseEscapeOptionsTest, RejectsBadValuesByName) {
  BaseEscapeOptions options;
  EXPECT_NO_THROW(CheckBaseEscapeOptions(options));
  options.num_directions = 3;
  EXPECT_THROW(CheckBaseEscapeOptions(options), std::invalid_argument);
  options = {};
  options.step_m = 0.0;
  try {
    CheckBaseEscapeOptions(options);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("step_m"), std::string::npos);
  }
}

// The base stands partly under a low table top behind it (the 2D field's upper band rejects
// it, the exact base is 3 mm clear): the nearest exit lies ahead (away from the table), is
// free on the field, and the straight move to it passes the zone's base check.
TEST_F(BaseEscapeTest, LeavesALowTableTopByTheNearestFreePosition) {
  const TightScene tight = MakeTightScene(kinematics_, TightSpot::kBaseUnderLowTableTop, 0.003);
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(tight.scene, PlannerFieldOptions(kinematics_));
  const SceneClearanceChecker checker(kinematics_, tight.scene);
  const WholeBodyValidity validity =
      WholeBodyValidity(kinematics_, fields.base_field_2d, fields.field_3d)
          .WithExactZones({&checker, {}, {{0.0, 0.0}}});
  const double clearance_m = 0.1;
  const BaseFreeSpace free_space(fields.base_field_2d,
                                 model_.base_cylinder.radius_m + clearance_m);
  ASSERT_FALSE(free_space.IsFree({0.0, 0.0}));
  ASSERT_TRUE(validity.IsBaseValid({0.0, 0.0}));
  ASSERT_FALSE(validity.IsBaseValidOnField({0.0, 0.0}));

  const auto escape = FindBaseEscape(free_space, validity, {0.0, 0.0}, 0.0);
  ASSERT_TRUE(escape.has_value());
  ASSERT_EQ(escape->waypoints_W_m.size(), 1u);  // a straight move
  const Eigen::Vector2d* exit = &escape->exit();
  EXPECT_TRUE(free_space.IsFree(*exit));
  EXPECT_GT(exit->x(), 0.0) << exit->transpose();  // away from the table behind
  EXPECT_LE(exit->norm(), BaseEscapeOptions{}.max_distance_m + 1e-9);
  // Nearest: no position on a smaller ring is free.
  const double step_m = BaseEscapeOptions{}.step_m;
  for (double r = step_m; r < exit->norm() - 1e-9; r += step_m) {
    for (int k = 0; k < 32; ++k) {
      const double a = 2.0 * 3.14159265358979 * k / 32;
      EXPECT_FALSE(free_space.IsFree(Eigen::Vector2d(r * std::cos(a), r * std::sin(a))))
          << "ring " << r;
    }
  }
  // Outside every zone the base check is the field's alone: no escape through exact space.
  const WholeBodyValidity fields_only(kinematics_, fields.base_field_2d, fields.field_3d);
  EXPECT_FALSE(FindBaseEscape(free_space, fields_only, {0.0, 0.0}, 0.0).has_value());
}

// A pocket: the base stands in the open middle of a square frame of low table tops (bottom
// 0.50 m, above the rigid shoulder's 0.4915 m top but within the 2D field's upper band), so
// the field accepts the base where it stands but cuts it off from the room around the frame.
// Given the region the other end reaches, the escape leaves the pocket under the frame (the
// exact base check passes there) for a free position of that region.
TEST_F(BaseEscapeTest, LeavesAPocketForTheRegionTheOtherEndReaches) {
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6));
  const double inner = 0.35, width = 0.2, z = 0.52, thick = 0.04;
  const double mid = inner + width / 2, length = 2 * (inner + width);
  scene.boxes.push_back(MakeBox({mid, 0.0, z}, {width, length, thick}));
  scene.boxes.push_back(MakeBox({-mid, 0.0, z}, {width, length, thick}));
  scene.boxes.push_back(MakeBox({0.0, mid, z}, {length, width, thick}));
  scene.boxes.push_back(MakeBox({0.0, -mid, z}, {length, width, thick}));
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(scene, PlannerFieldOptions(kinematics_));
  const SceneClearanceChecker checker(kinematics_, scene);
  const WholeBodyValidity validity =
      WholeBodyValidity(kinematics_, fields.base_field_2d, fields.field_3d)
          .WithExactZones({&checker, {}, {{0.0, 0.0}}});
  const double safe_m = model_.base_cylinder.radius_m + 0.1;
  const BaseFreeSpace free_space(fields.base_field_2d, safe_m);
  const BaseReachableRegion room(fields.base_field_2d, {3.0, 0.0}, safe_m);
  ASSERT_TRUE(room.start_joins_grid());
  ASSERT_TRUE(free_space.IsFree({0.0, 0.0})) << fields.base_field_2d.Distance({0.0, 0.0});
  ASSERT_FALSE(room.Contains({0.0, 0.0}));

  const auto escape = FindBaseEscape(free_space, validity, {0.0, 0.0}, 0.0, {}, &room);
  ASSERT_TRUE(escape.has_value());
  EXPECT_TRUE(room.Contains(escape->exit())) << escape->exit().transpose();
  EXPECT_LE(escape->exit().norm(), BaseEscapeOptions{}.max_distance_m + 1e-9);
  // Every move of the route passes the zone's base check, checked afresh every 5 mm.
  Eigen::Vector2d from(0.0, 0.0);
  for (const Eigen::Vector2d& to : escape->waypoints_W_m) {
    for (int k = 0; k <= 100; ++k) {
      EXPECT_TRUE(validity.IsBaseValid(from + (to - from) * (k / 100.0))) << to.transpose();
    }
    from = to;
  }
  // Without the region the base is already out (free where it stands); without the zone the
  // frame's shadow holds it.
  const auto in_place = FindBaseEscape(free_space, validity, {0.0, 0.0}, 0.0);
  ASSERT_TRUE(in_place.has_value());
  EXPECT_LT(in_place->exit().norm(), inner);
  const WholeBodyValidity fields_only(kinematics_, fields.base_field_2d, fields.field_3d);
  EXPECT_FALSE(
      FindBaseEscape(free_space, fields_only, {0.0, 0.0}, 0.0, {}, &room).has_value());
}

// Walled in on every side within the escape distance: no exit.
TEST_F(BaseEscapeTest, NoExitWhenWalledIn) {
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6));
  for (const Eigen::Vector3d& wall : {Eigen::Vector3d(0.45, 0, 0.5), Eigen::Vector3d(-0.45, 0, 0.5)}) {
    scene.boxes.push_back(MakeBox(wall, {0.04, 1.0, 1.0}));
  }
  for (const Eigen::Vector3d& wall : {Eigen::Vector3d(0, 0.45, 0.5), Eigen::Vector3d(0, -0.45, 0.5)}) {
    scene.boxes.push_back(MakeBox(wall, {1.0, 0.04, 1.0}));
  }
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene, PlannerFieldOptions(kinematics_));
  const SceneClearanceChecker checker(kinematics_, scene);
  const WholeBodyValidity validity =
      WholeBodyValidity(kinematics_, fields.base_field_2d, fields.field_3d)
          .WithExactZones({&checker, {}, {{0.0, 0.0}}});
  // 3 cm of room on each side, the search needs 10 cm.
  const BaseFreeSpace free_space(fields.base_field_2d, model_.base_cylinder.radius_m + 0.1);
  ASSERT_FALSE(free_space.IsFree({0.0, 0.0}));
  ASSERT_TRUE(validity.IsBaseValid({0.0, 0.0}));
  EXPECT_FALSE(FindBaseEscape(free_space, validity, {0.0, 0.0}, 0.0).has_value());
  EXPECT_FALSE(FindBaseEscape(free_space, validity, {std::nan(""), 0.0}, 0.0).has_value());
}

// No straight way out: the base stands in a corridor of tall walls (open at +x only) under a
// table top that covers the corridor and the room beyond its end, so every position the field
// accepts lies beside the corridor; the escape is a bent route (out of the corridor's end,
// then sideways), each move of which passes the base check.
TEST_F(BaseEscapeTest, BentRouteWhenNoStraightMoveLeadsOut) {
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6));
  scene.boxes.push_back(MakeBox({-0.175, 0.45, 0.6}, {0.85, 0.04, 1.2}));   // corridor walls,
  scene.boxes.push_back(MakeBox({-0.175, -0.45, 0.6}, {0.85, 0.04, 1.2}));  // x -0.6 .. 0.25
  scene.boxes.push_back(MakeBox({-0.6, 0.0, 0.6}, {0.04, 0.94, 1.2}));      // closed behind
  scene.boxes.push_back(MakeBox({1.25, 0.0, 0.6}, {0.04, 1.2, 1.2}));       // a wall ahead
  scene.boxes.push_back(MakeBox({0.35, 0.0, 0.5}, {1.9, 1.2, 0.04}));       // the table top
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene, PlannerFieldOptions(kinematics_));
  const SceneClearanceChecker checker(kinematics_, scene);
  const WholeBodyValidity validity =
      WholeBodyValidity(kinematics_, fields.base_field_2d, fields.field_3d)
          .WithExactZones({&checker, {1.5}, {{0.0, 0.0}}});
  const BaseFreeSpace free_space(fields.base_field_2d, model_.base_cylinder.radius_m + 0.1);
  ASSERT_FALSE(free_space.IsFree({0.0, 0.0}));
  ASSERT_TRUE(validity.IsBaseValid({0.0, 0.0}));
  BaseEscapeOptions options;
  options.max_distance_m = 1.5;

  BaseEscapeOptions straight_only = options;
  straight_only.route_step_m = 0.0;
  EXPECT_FALSE(FindBaseEscape(free_space, validity, {0.0, 0.0}, 0.0, straight_only).has_value());

  const auto escape = FindBaseEscape(free_space, validity, {0.0, 0.0}, 0.0, options);
  ASSERT_TRUE(escape.has_value());
  EXPECT_GE(escape->waypoints_W_m.size(), 2u) << escape->exit().transpose();
  EXPECT_TRUE(free_space.IsFree(escape->exit())) << escape->exit().transpose();
  EXPECT_GT(escape->exit().x(), 0.25);  // out of the corridor's open end
  EXPECT_LE((escape->exit()).norm(), options.max_distance_m + 1e-9);
  Eigen::Vector2d from(0.0, 0.0);
  double length_m = 0.0;
  for (const Eigen::Vector2d& to : escape->waypoints_W_m) {
    length_m += (to - from).norm();
    for (int k = 0; k <= 200; ++k) {
      const Eigen::Vector2d p = from + (to - from) * (k / 200.0);
      ASSERT_TRUE(validity.IsBaseValid(p)) << p.transpose();
      EXPECT_GT(checker.BaseClearance(p, 1.0), 0.0) << p.transpose();
    }
    from = to;
  }
  EXPECT_NEAR(escape->LengthFrom({0.0, 0.0}), length_m, 1e-12);
}

}  // namespace
}  // namespace topay
