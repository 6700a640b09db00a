// The whole planner at close quarters: starts and goals a few millimetres from a box (next to
// it, under a table top, the base under a low table top, beside a floating cube) are planned
// out of and into, every success accepted by the independent validator; a millimetre in
// collision is refused with the body and the box named.

#include <cctype>
#include <string>

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/planner/plan_in_scene.h"
#include "core/robot/kinematics.h"
#include "tests/common/tight_scenes.h"

namespace topay {
namespace {

class CloseQuartersTest : public ::testing::TestWithParam<TightSpot> {
 protected:
  CloseQuartersTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  static WholeBodyPlannerOptions Options() {
    WholeBodyPlannerOptions options;
    BaseLimits limits;
    limits.omega_max_radps = 1.25;
    options.base_limits = limits;
    options.time_limit_s = 20.0;  // generous: the outcome, not the speed, is tested here
    options.optimizer.time_limit_s = 20.0;
    options.front_end.acquisition_budget_s = 5.0;
    options.front_end.ik.time_budget_s = 1.0;
    return options;
  }

  WholeBodyState OpenState() const { return BentArmState(-2.5, 0.5, 1.0); }

  // A success must carry the validator's acceptance.
  static void ExpectValidated(const ScenePlan& plan, const std::string& what) {
    ASSERT_TRUE(plan.result.success()) << what << ": " << plan.result.failure_reason;
    ASSERT_GE(plan.result.chosen, 0);
    const CandidateReport& chosen = plan.result.candidates[plan.result.chosen];
    ASSERT_TRUE(chosen.validation.has_value());
    EXPECT_TRUE(chosen.validation->ok);
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_P(CloseQuartersTest, PlansOutOfATightStart) {
  const TightScene tight = MakeTightScene(kinematics_, GetParam(), 0.003);
  const ScenePlan plan = PlanInScene(kinematics_, tight.scene, Options(), tight.state,
                                     kinematics_.EndEffectorPose(OpenState()), OpenState());
  ExpectValidated(plan, TightSpotName(GetParam()));
  EXPECT_TRUE(plan.result.front_end.stats.start_in_exact_zone);
}

TEST_P(CloseQuartersTest, PlansIntoATightGoalGivenAsTheHint) {
  const TightScene tight = MakeTightScene(kinematics_, GetParam(), 0.003);
  const ScenePlan plan = PlanInScene(kinematics_, tight.scene, Options(), OpenState(),
                                     kinematics_.EndEffectorPose(tight.state), tight.state);
  ExpectValidated(plan, TightSpotName(GetParam()));
  EXPECT_TRUE(plan.result.front_end.stats.goal_from_hint);
}

TEST_P(CloseQuartersTest, AStartAMillimetreInCollisionIsRefusedNamingBodyAndBox) {
  const TightScene tight = MakeTightScene(kinematics_, GetParam(), -0.001);
  const ScenePlan plan = PlanInScene(kinematics_, tight.scene, Options(), tight.state,
                                     kinematics_.EndEffectorPose(OpenState()), OpenState());
  EXPECT_FALSE(plan.result.success());
  EXPECT_EQ(plan.result.front_end.status, FrontEndStatus::kStartInvalid);
  const std::string& why = plan.result.failure_reason;
  EXPECT_NE(why.find("penetrates box " + std::to_string(tight.box)), std::string::npos) << why;
  EXPECT_NE(why.find("by 0.001 m"), std::string::npos) << why;
  EXPECT_TRUE(why.find("the base") != std::string::npos ||
              why.find("arm sphere") != std::string::npos)
      << why;
}

INSTANTIATE_TEST_SUITE_P(Spots, CloseQuartersTest,
                         ::testing::Values(TightSpot::kNextToBox, TightSpot::kUnderTableTop,
                                           TightSpot::kBaseUnderLowTableTop,
                                           TightSpot::kBesideFloatingCube),
                         [](const auto& info) {
                           std::string name = TightSpotName(info.param);
                           std::string out;
                           bool upper = true;
                           for (char c : name) {
                             if (c == ' ') {
                               upper = true;
                             } else {
                               out += upper ? static_cast<char>(std::toupper(c)) : c;
                               upper = false;
                             }
                           }
                           return out;
                         });

}  // namespace
}  // namespace topay
