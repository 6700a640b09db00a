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
#include "tests/common/make_box.h"
#include "tests/common/tight_scenes.h"

namespace topay {
namespace {

class CloseQuartersTest : public ::testing::TestWithParam<TightSpot> {
 public:
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

// A pocket the fields accept the start in but not the way out: the base stands 0.43 m from
// the pocket's walls (valid on the 2D field, closer than the base path search's clearance),
// and the only way out runs between two low table tops whose shadow on the 2D field rejects
// the base (the exact scene: the base passes under them, the shoulder between them). The
// planner plans out of it (start in an exact zone, an escape route, the optimizer relieved
// along the route by its own deficits, the primary band keeping the walls), and the
// validator accepts the trajectory.
TEST(CloseQuartersPocketTest, PlansOutOfAPocketWhoseWayOutOnlyTheExactSceneAccepts) {
  const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                          TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6));
  scene.boxes.push_back(MakeBox({0.92, 0.0, 0.6}, {0.04, 1.0, 1.2}));    // the pocket's end
  scene.boxes.push_back(MakeBox({0.15, 0.47, 0.6}, {1.5, 0.04, 1.2}));   // its sides,
  scene.boxes.push_back(MakeBox({0.15, -0.47, 0.6}, {1.5, 0.04, 1.2}));  // x -0.6 .. 0.9
  scene.boxes.push_back(MakeBox({-0.425, 0.82, 0.5}, {0.35, 1.3, 0.04}));   // table tops over
  scene.boxes.push_back(MakeBox({-0.425, -0.82, 0.5}, {0.35, 1.3, 0.04}));  // x -0.6 .. -0.25
  const WholeBodyState start = BentArmState(0.0, 0.0, 0.0);
  const WholeBodyState goal = BentArmState(-2.5, 0.5, 1.0);
  WholeBodyPlannerOptions options = CloseQuartersTest::Options();
  const ScenePlan plan =
      PlanInScene(kinematics, scene, options, start, kinematics.EndEffectorPose(goal), goal);
  ASSERT_TRUE(plan.result.success()) << plan.result.failure_reason;
  ASSERT_GE(plan.result.chosen, 0);
  const CandidateReport& chosen = plan.result.candidates[plan.result.chosen];
  ASSERT_TRUE(chosen.validation.has_value());
  EXPECT_TRUE(chosen.validation->ok) << chosen.validation->first_failure.message;
  EXPECT_FALSE(plan.result.front_end.stats.start_in_exact_zone);  // valid on the fields
  EXPECT_TRUE(plan.result.front_end.stats.start_base_escape);     // but not its way out
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
