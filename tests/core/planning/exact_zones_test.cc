#include "core/planning/exact_zones.h"

#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/front_end.h"
#include "core/planning/path_verification.h"
#include "core/planning/planner_fields.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/kinematics.h"
#include "tests/common/tight_scenes.h"

namespace topay {
namespace {

constexpr double kClear_m = 0.003;      // a few millimetres clear
constexpr double kColliding_m = -0.001;  // a millimetre in collision

FrontEndOptions DeterministicOptions() {
  FrontEndOptions options;
  options.ik.time_budget_s = std::numeric_limits<double>::infinity();
  options.goal_retry.time_budget_s = std::numeric_limits<double>::infinity();
  options.topology.prm.max_time_s = 0.0;
  options.topology.prm.max_samples = 2000;
  options.rrt.time_budget_s = std::numeric_limits<double>::infinity();
  options.rrt.max_iterations = 5000;
  options.rrt.stop_at_first_solution = true;
  options.improvement_window_s = std::numeric_limits<double>::infinity();
  options.acquisition_budget_s = std::numeric_limits<double>::infinity();
  return options;
}

class ExactZonesTest : public ::testing::TestWithParam<TightSpot> {
 protected:
  ExactZonesTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  WholeBodyValidity validity_of(const SceneDistanceFields& fields) const {
    return WholeBodyValidity(kinematics_, fields.base_field_2d, fields.field_3d);
  }

  // The open far corner of the room the plans go to or come from.
  WholeBodyState OpenState() const { return BentArmState(-2.5, 0.5, 1.0); }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST(ExactZoneOptionsTest, RejectsBadValuesByName) {
  ExactZoneOptions options;
  EXPECT_NO_THROW(CheckExactZoneOptions(options));
  options.radius_m = -1.0;
  EXPECT_THROW(CheckExactZoneOptions(options), std::invalid_argument);
  options = {};
  options.obstacle_margin_m = std::numeric_limits<double>::quiet_NaN();
  try {
    CheckExactZoneOptions(options);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("obstacle_margin_m"), std::string::npos);
  }
}

TEST(ExactZonesContainsTest, ByBaseDistanceAndOnlyWithAChecker) {
  ExactZones zones;
  zones.centres_W_m = {{1.0, 0.0}};
  EXPECT_TRUE(zones.empty());
  EXPECT_FALSE(zones.Contains(Eigen::Vector2d(1.0, 0.0)));  // no checker: no zone
  const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                          TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  const Scene scene;
  const SceneClearanceChecker checker(kinematics, scene);
  zones.checker = &checker;
  zones.options.radius_m = 0.5;
  EXPECT_TRUE(zones.Contains(Eigen::Vector2d(1.4, 0.3)));
  EXPECT_FALSE(zones.Contains(Eigen::Vector2d(1.4, 0.31)));
}

// The fields reject the tight state (otherwise this test would not test the zones); in its
// zone the exact scene accepts it; a millimetre deeper it is an exact collision; out of the
// zone the fields alone decide.
TEST_P(ExactZonesTest, ZonesAcceptExactlyClearStatesTheFieldsReject) {
  const TightScene clear = MakeTightScene(kinematics_, GetParam(), kClear_m);
  ASSERT_NEAR(ObstacleClearance(kinematics_, clear.scene, clear.state), kClear_m, 1e-6);
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(clear.scene, PlannerFieldOptions(kinematics_));
  const WholeBodyValidity validity(kinematics_, fields.base_field_2d, fields.field_3d);
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  const ValidityFailure on_fields = validity.Check(clear.state, &workspace);
  ASSERT_TRUE(on_fields == ValidityFailure::kBaseCollision ||
              on_fields == ValidityFailure::kArmCollision)
      << TightSpotName(GetParam()) << ": " << ToString(on_fields);

  const SceneClearanceChecker checker(kinematics_, clear.scene);
  const WholeBodyValidity zoned = validity.WithExactZones({&checker, {}, {{0.0, 0.0}}});
  EXPECT_EQ(zoned.Check(clear.state, &workspace), ValidityFailure::kNone);
  EXPECT_EQ(zoned.CheckOnFields(clear.state, &workspace), on_fields);
  const WholeBodyValidity elsewhere = validity.WithExactZones({&checker, {}, {{3.0, 3.0}}});
  EXPECT_EQ(elsewhere.Check(clear.state, &workspace), on_fields);

  const TightScene colliding = MakeTightScene(kinematics_, GetParam(), kColliding_m);
  const SceneClearanceChecker colliding_checker(kinematics_, colliding.scene);
  const WholeBodyValidity colliding_zoned =
      validity.WithExactZones({&colliding_checker, {}, {{0.0, 0.0}}});
  EXPECT_EQ(colliding_zoned.Check(colliding.state, &workspace), ValidityFailure::kExactCollision);
  // A margin larger than the clearance rejects the clear state too.
  ExactZoneOptions strict;
  strict.obstacle_margin_m = 2.0 * kClear_m;
  EXPECT_EQ(validity.WithExactZones({&checker, strict, {{0.0, 0.0}}}).Check(clear.state, &workspace),
            ValidityFailure::kExactCollision);
}

// As a start: the front end plans out of the tight spot, every path exactly clear
// (independent check), its first states marked as validated exactly; without an exact
// checker the same start is refused on the fields.
TEST_P(ExactZonesTest, FrontEndPlansOutOfATightStart) {
  const TightScene tight = MakeTightScene(kinematics_, GetParam(), kClear_m);
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(tight.scene, PlannerFieldOptions(kinematics_));
  const SceneClearanceChecker checker(kinematics_, tight.scene);
  const Eigen::Isometry3d X_WE_goal = kinematics_.EndEffectorPose(OpenState());

  const FrontEnd fields_only(kinematics_, fields.base_field_2d, fields.field_3d,
                             DeterministicOptions());
  const FrontEndResult refused = fields_only.Plan(tight.state, X_WE_goal, OpenState());
  EXPECT_EQ(refused.status, FrontEndStatus::kStartInvalid) << refused.failure_reason;

  const FrontEnd front_end(kinematics_, fields.base_field_2d, fields.field_3d,
                           DeterministicOptions(), &checker);
  const FrontEndResult result = front_end.Plan(tight.state, X_WE_goal, OpenState());
  ASSERT_EQ(result.status, FrontEndStatus::kSuccess)
      << TightSpotName(GetParam()) << ": " << result.failure_reason;
  EXPECT_TRUE(result.stats.start_in_exact_zone);
  // The base under a low table top: the 2D field rejects the base itself, so the base path
  // search starts from an escape position.
  const bool base_trapped = !validity_of(fields).IsBaseValidOnField({0.0, 0.0});
  EXPECT_EQ(base_trapped, GetParam() == TightSpot::kBaseUnderLowTableTop);
  if (base_trapped) {
    EXPECT_TRUE(result.stats.start_base_escape);
  }
  for (const FrontEndPath& path : result.paths) {
    EXPECT_GT(path.exact_prefix_states, 0);
    EXPECT_EQ(path.exact_suffix_states, 0);
    const PathVerification check =
        VerifyWholeBodyPath(path.path, tight.state, X_WE_goal, checker, kinematics_);
    EXPECT_TRUE(check.ok) << check.message;
  }
}

// As a hint and goal: the tight goal state is taken as is, and the paths end in it.
TEST_P(ExactZonesTest, FrontEndTakesATightHintAsTheGoal) {
  const TightScene tight = MakeTightScene(kinematics_, GetParam(), kClear_m);
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(tight.scene, PlannerFieldOptions(kinematics_));
  const SceneClearanceChecker checker(kinematics_, tight.scene);
  const Eigen::Isometry3d X_WE_goal = kinematics_.EndEffectorPose(tight.state);
  const FrontEnd front_end(kinematics_, fields.base_field_2d, fields.field_3d,
                           DeterministicOptions(), &checker);
  const FrontEndResult result = front_end.Plan(OpenState(), X_WE_goal, tight.state);
  ASSERT_EQ(result.status, FrontEndStatus::kSuccess)
      << TightSpotName(GetParam()) << ": " << result.failure_reason;
  EXPECT_TRUE(result.stats.goal_from_hint);
  EXPECT_TRUE(result.stats.goal_in_exact_zone);
  EXPECT_GE(result.stats.goal_clearance.exact_accepted, 1);
  EXPECT_TRUE(result.goal.q_rad.isApprox(tight.state.q_rad));
  for (const FrontEndPath& path : result.paths) {
    EXPECT_GT(path.exact_suffix_states, 0);
    const PathVerification check =
        VerifyWholeBodyPath(path.path, OpenState(), X_WE_goal, checker, kinematics_);
    EXPECT_TRUE(check.ok) << check.message;
  }
}

// A millimetre in collision: refused as a start, naming the body and the box; not taken as
// a hint (the exact check rejects it and says so in the tally).
TEST_P(ExactZonesTest, AMillimetreInCollisionIsRefusedWithBodyAndBox) {
  const TightScene tight = MakeTightScene(kinematics_, GetParam(), kColliding_m);
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(tight.scene, PlannerFieldOptions(kinematics_));
  const SceneClearanceChecker checker(kinematics_, tight.scene);
  FrontEndOptions options = DeterministicOptions();
  const FrontEnd front_end(kinematics_, fields.base_field_2d, fields.field_3d, options, &checker);
  const FrontEndResult as_start =
      front_end.Plan(tight.state, kinematics_.EndEffectorPose(OpenState()), OpenState());
  EXPECT_EQ(as_start.status, FrontEndStatus::kStartInvalid);
  EXPECT_NE(as_start.failure_reason.find("penetrates box " + std::to_string(tight.box) +
                                         " (centre"),
            std::string::npos)
      << as_start.failure_reason;
  EXPECT_NE(as_start.failure_reason.find("by 0.001 m"), std::string::npos)
      << as_start.failure_reason;
  EXPECT_TRUE(as_start.failure_reason.find("the base") != std::string::npos ||
              as_start.failure_reason.find("arm sphere") != std::string::npos)
      << as_start.failure_reason;

  const FrontEndResult as_goal =
      front_end.Plan(OpenState(), kinematics_.EndEffectorPose(tight.state), tight.state);
  EXPECT_FALSE(as_goal.stats.goal_from_hint && as_goal.success());
  const GoalClearanceTally& tally = as_goal.stats.goal_clearance;
  EXPECT_GE(tally.exact_arm + tally.exact_base, 1) << tally.Describe();
}

INSTANTIATE_TEST_SUITE_P(Spots, ExactZonesTest,
                         ::testing::Values(TightSpot::kNextToBox, TightSpot::kUnderTableTop,
                                           TightSpot::kBaseUnderLowTableTop,
                                           TightSpot::kBesideFloatingCube),
                         [](const auto& info) {
                           switch (info.param) {
                             case TightSpot::kNextToBox:
                               return std::string("NextToBox");
                             case TightSpot::kUnderTableTop:
                               return std::string("UnderTableTop");
                             case TightSpot::kBaseUnderLowTableTop:
                               return std::string("BaseUnderLowTableTop");
                             default:
                               return std::string("BesideFloatingCube");
                           }
                         });

}  // namespace
}  // namespace topay
