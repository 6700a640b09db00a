#include "core/planning/goal_clearance.h"

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/field_clearance.h"
#include "core/planning/planner_fields.h"
#include "tests/common/tight_scenes.h"

namespace topay {
namespace {

class GoalClearanceTest : public ::testing::Test {
 protected:
  GoalClearanceTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  RobotModel model_;
  Kinematics kinematics_;
};

// Clear on the fields: the fields' clearance; rejected by the fields, exactly clear: the tiny
// positive value; a millimetre in: -1 with the exact reason counted; a joint limit: -1.
TEST_F(GoalClearanceTest, DecidesByTheFieldsThenExactlyAndCountsWhy) {
  const TightScene tight = MakeTightScene(kinematics_, TightSpot::kBesideFloatingCube, 0.004);
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(tight.scene, PlannerFieldOptions(kinematics_));
  const WholeBodyValidity validity(kinematics_, fields.base_field_2d, fields.field_3d);
  const SceneClearanceChecker checker(kinematics_, tight.scene);
  GoalClearance clearance(validity, fields.base_field_2d, fields.field_3d, &checker, {});

  const WholeBodyState open = BentArmState(-2.5, 0.5, 1.0);
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  EXPECT_DOUBLE_EQ(clearance(open), FieldClearance(validity, fields.base_field_2d,
                                                   fields.field_3d, open, &workspace));
  EXPECT_GT(clearance(open), GoalClearance::kExactOnlyClearance);
  EXPECT_EQ(clearance(tight.state), GoalClearance::kExactOnlyClearance);

  ExactZoneOptions strict;
  strict.obstacle_margin_m = 0.005;  // above the 4 mm: rejected exactly, as an arm sphere
  GoalClearance strict_clearance(validity, fields.base_field_2d, fields.field_3d, &checker, strict);
  EXPECT_EQ(strict_clearance(tight.state), -1.0);
  EXPECT_EQ(strict_clearance.tally().exact_arm, 1);

  WholeBodyState beyond_limit = open;
  beyond_limit.q_rad(1) = model_.joint_limits.q_max_rad(1) + 0.1;
  EXPECT_EQ(clearance(beyond_limit), -1.0);

  const GoalClearanceTally& tally = clearance.tally();
  EXPECT_EQ(tally.field_accepted, 2);
  EXPECT_EQ(tally.exact_accepted, 1);
  EXPECT_EQ(tally.joint_limit, 1);
  EXPECT_EQ(tally.rejected(), 1);
  EXPECT_NE(tally.Describe().find("1 clear only exactly"), std::string::npos) << tally.Describe();
  EXPECT_NE(tally.Describe().find("1 joint limit"), std::string::npos) << tally.Describe();

  // Without an exact checker, the fields' rejection stands.
  GoalClearance fields_only(validity, fields.base_field_2d, fields.field_3d, nullptr, {});
  EXPECT_EQ(fields_only(tight.state), -1.0);
  EXPECT_EQ(fields_only.tally().field_only, 1);
}

}  // namespace
}  // namespace topay
