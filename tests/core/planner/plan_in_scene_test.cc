#include "core/planner/plan_in_scene.h"

#include <ctime>
#include <string>

#include <gtest/gtest.h>

#include "tests/common/arm_state.h"

#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "tests/common/make_box.h"

namespace topay {
namespace {

// Process CPU time (s), all threads: bounds that do not depend on how loaded the machine is.
double CpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

class PlanInSceneTest : public ::testing::Test {
 protected:
  PlanInSceneTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  // A 10 x 10 m room with one pillar between start and goal.
  static Scene PillarRoom() {
    Scene scene;
    scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(0, 0, 0.75), Eigen::Vector3d(1.0, 1.0, 1.5)));
    return scene;
  }

  // `count` small floor boxes (3-8 cm, up to 30 cm tall) over the 20 x 20 m room, none
  // within 1 m of the start's and the goal's base positions.
  static Scene Clutter(int count) {
    Scene scene;
    Rng rng(13);
    while (static_cast<int>(scene.boxes.size()) < count) {
      const Eigen::Vector2d p(rng.Uniform(-9.8, 9.8), rng.Uniform(-9.8, 9.8));
      if ((p - Eigen::Vector2d(-3, 0)).norm() < 1.0 || (p - Eigen::Vector2d(3, 0.5)).norm() < 1.0) {
        continue;
      }
      const double height = rng.Uniform(0.05, 0.3);
      scene.boxes.push_back(MakeBox(Eigen::Vector3d(p.x(), p.y(), 0.5 * height),
                                    Eigen::Vector3d(rng.Uniform(0.03, 0.08),
                                                    rng.Uniform(0.03, 0.08), height),
                                    rng.Uniform(-3.2, 3.2)));
    }
    return scene;
  }

  WholeBodyState State(double x, double y, double yaw) const { return BentArmState(x, y, yaw); }

  static WholeBodyPlannerOptions Options(double time_limit_s) {
    WholeBodyPlannerOptions options;
    BaseLimits limits;
    limits.omega_max_radps = 1.25;
    options.base_limits = limits;
    options.time_limit_s = time_limit_s;
    options.optimizer.time_limit_s = 10.0;
    options.front_end.acquisition_budget_s = 5.0;
    return options;
  }

  RobotModel model_;
  Kinematics kinematics_;
};

// 100,000 boxes and a 0.3 s limit: the plan ends by the limit, says so and in which stage.
// The bound asserted is on CPU time and generous (10 s for a 0.3 s limit); the old build of
// the exact base field alone took about 50 s of CPU here.
TEST_F(PlanInSceneTest, AHugeSceneWithAShortLimitEndsByTheLimit) {
  const Scene scene = Clutter(100000);
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(State(3.0, 0.5, 1.0));
  const double cpu0 = CpuSeconds();
  const ScenePlan plan = PlanInScene(kinematics_, scene, Options(0.3), start, X_WE);
  const double cpu_s = CpuSeconds() - cpu0;
  const WholeBodyPlanResult& result = plan.result;
  ASSERT_EQ(result.status, PlanStatus::kTimeLimit) << result.Report();
  EXPECT_NE(result.stopped_stage, PlanStage::kNone);
  EXPECT_NE(result.stopped_stage, PlanStage::kStartCheck);
  EXPECT_NE(result.failure_reason.find("time limit 0.300 s reached during"), std::string::npos)
      << result.failure_reason;
  EXPECT_FALSE(result.trajectory.has_value());
  EXPECT_LT(cpu_s, 10.0) << result.Report();
  if (result.stopped_stage == PlanStage::kMapBuilding) {
    EXPECT_FALSE(plan.fields.has_value());
  }
}

// A start in collision is found exactly and at once: no field is built.
TEST_F(PlanInSceneTest, AStartInCollisionIsReportedBeforeAnyFieldIsBuilt) {
  const Scene scene = Clutter(100000);
  const OrientedBox& box = scene.boxes[777];
  const WholeBodyState start = State(box.center_W_m.x(), box.center_W_m.y(), 0.0);
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(State(3.0, 0.5, 1.0));
  const ScenePlan plan = PlanInScene(kinematics_, scene, Options(60.0), start, X_WE);
  const WholeBodyPlanResult& result = plan.result;
  EXPECT_EQ(result.status, PlanStatus::kFrontEndFailed) << result.Report();
  EXPECT_EQ(result.front_end.status, FrontEndStatus::kStartInvalid);
  // The exact diagnosis names the body and the box.
  EXPECT_NE(result.failure_reason.find("start state: the base"), std::string::npos)
      << result.failure_reason;
  EXPECT_NE(result.failure_reason.find("penetrates box"), std::string::npos)
      << result.failure_reason;
  EXPECT_FALSE(plan.fields.has_value());
  EXPECT_EQ(result.timings.map_ms, 0.0);
  EXPECT_EQ(result.timings.front_end_ms, 0.0);  // the front end never ran
  EXPECT_GT(result.timings.start_check_ms, 0.0);
}

TEST_F(PlanInSceneTest, ATargetInsideABoxOrOutsideTheSceneIsReportedBeforeAnyField) {
  const Scene scene = PillarRoom();
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  Eigen::Isometry3d inside = kinematics_.EndEffectorPose(State(3.0, 0.5, 1.0));
  inside.translation() << 0.1, 0.0, 0.8;  // inside the pillar (box 0)
  ScenePlan plan = PlanInScene(kinematics_, scene, Options(60.0), start, inside);
  EXPECT_EQ(plan.result.front_end.status, FrontEndStatus::kNoGoal) << plan.result.Report();
  EXPECT_NE(plan.result.failure_reason.find("inside box 0"), std::string::npos)
      << plan.result.failure_reason;
  EXPECT_FALSE(plan.fields.has_value());
  Eigen::Isometry3d below = inside;
  below.translation() << 2.0, 2.0, -0.2;
  plan = PlanInScene(kinematics_, scene, Options(60.0), start, below);
  EXPECT_EQ(plan.result.front_end.status, FrontEndStatus::kNoGoal) << plan.result.Report();
  EXPECT_NE(plan.result.failure_reason.find("below the floor"), std::string::npos)
      << plan.result.failure_reason;
  EXPECT_FALSE(plan.fields.has_value());
}

// The ordinary case: checks, fields, plan; the stage times add up inside the total.
TEST_F(PlanInSceneTest, PlansAroundThePillarWithTheMapInsideTheTotal) {
  const Scene scene = PillarRoom();
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const ScenePlan plan =
      PlanInScene(kinematics_, scene, Options(60.0), start, kinematics_.EndEffectorPose(goal), goal);
  const WholeBodyPlanResult& result = plan.result;
  ASSERT_TRUE(result.success()) << result.Report();
  ASSERT_TRUE(plan.fields.has_value());
  EXPECT_EQ(result.stopped_stage, PlanStage::kNone);
  EXPECT_GT(result.timings.map_ms, 0.0);
  EXPECT_GE(result.timings.total_ms, result.timings.start_check_ms + result.timings.map_ms +
                                         result.timings.front_end_ms);
}

// A deadline already passed: the planner stops in the front end and says so.
TEST_F(PlanInSceneTest, APassedDeadlineStopsThePlannerInTheFrontEnd) {
  const Scene scene = PillarRoom();
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene, PlannerFieldOptions(kinematics_));
  const WholeBodyPlanner planner(kinematics_, fields.base_field_2d, fields.field_3d, scene,
                                 Options(60.0));
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const WholeBodyPlanResult result =
      planner.PlanBy(std::chrono::steady_clock::now(), State(-3.0, 0.0, 0.0),
                     kinematics_.EndEffectorPose(goal), goal);
  EXPECT_EQ(result.status, PlanStatus::kTimeLimit) << result.Report();
  EXPECT_EQ(result.stopped_stage, PlanStage::kFrontEnd);
  EXPECT_NE(result.failure_reason.find("reached during front end"), std::string::npos)
      << result.failure_reason;
}

}  // namespace
}  // namespace topay
