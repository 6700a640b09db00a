#include "core/collision/start_target_diagnosis.h"

#include <string>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "tests/common/make_box.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class StartTargetDiagnosisTest : public ::testing::Test {
 protected:
  StartTargetDiagnosisTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}

  WholeBodyState Stowed(double x, double y) const {
    WholeBodyState state;
    state.x_m = x;
    state.y_m = y;
    state.q_rad = model_.stow_q_rad.size() > 0 ? model_.stow_q_rad
                                               : Eigen::VectorXd::Zero(model_.num_joints());
    return state;
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(StartTargetDiagnosisTest, AClearStartHasNoDiagnosis) {
  Scene scene;
  scene.boxes.push_back(MakeBox({3, 0, 0.5}, {1, 1, 1}, 0.0));
  const WholeBodyState start = Stowed(0, 0);
  ASSERT_TRUE(SceneClearanceChecker(kinematics_, scene).Compute(start).IsCollisionFree());
  EXPECT_EQ(DiagnoseStartState(kinematics_, scene, start), std::nullopt);
}

TEST_F(StartTargetDiagnosisTest, AJointOutsideItsLimitsIsNamed) {
  WholeBodyState start = Stowed(0, 0);
  start.q_rad(2) = model_.joint_limits.q_max_rad(2) + 0.2;
  const auto why = DiagnoseStartState(kinematics_, Scene{}, start);
  ASSERT_TRUE(why);
  EXPECT_TRUE(Has(*why, "joint '" + model_.joint_names[2] + "' (q3)")) << *why;
  EXPECT_TRUE(Has(*why, "outside its limits")) << *why;
  const auto malformed = DiagnoseStartState(kinematics_, Scene{}, WholeBodyState{});
  ASSERT_TRUE(malformed);
  EXPECT_TRUE(Has(*malformed, "joint values")) << *malformed;
}

TEST_F(StartTargetDiagnosisTest, ABaseInABoxNamesTheBox) {
  Scene scene;
  scene.boxes.push_back(MakeBox({-3, 0, 0.5}, {1, 1, 1}, 0.0));
  scene.boxes.push_back(MakeBox({0.6, 0, 0.5}, {0.5, 0.5, 1}, 0.0));  // base r 0.4
  const auto why = DiagnoseStartState(kinematics_, scene, Stowed(0, 0));
  ASSERT_TRUE(why);
  EXPECT_TRUE(Has(*why, "the base")) << *why;
  EXPECT_TRUE(Has(*why, "penetrates box 1 ")) << *why;
  EXPECT_TRUE(Has(*why, "by 0.050 m")) << *why;  // 0.4 - (0.6 - 0.25)
}

TEST_F(StartTargetDiagnosisTest, AnArmSphereInABoxNamesTheSphereLinkAndBox) {
  const WholeBodyState start = Stowed(0, 0);
  KinematicsCache cache = kinematics_.MakeCache();
  kinematics_.Update(start, &cache);
  // A small box at the centre of the highest sphere, clear of the base cylinder.
  int top = 0;
  for (int s = 1; s < static_cast<int>(cache.p_WS.size()); ++s) {
    if (cache.p_WS[s].z() > cache.p_WS[top].z()) top = s;
  }
  ASSERT_GT(cache.p_WS[top].z(), model_.base_cylinder.height_m + 0.05);
  Scene scene;
  scene.boxes.push_back(MakeBox(cache.p_WS[top], {0.02, 0.02, 0.02}, 0.0));
  const SceneClearance c = SceneClearanceChecker(kinematics_, scene).Compute(start);
  ASSERT_GT(c.base_m, 0.0);
  ASSERT_LT(c.spheres_m, 0.0);
  const auto why = DiagnoseStartState(kinematics_, scene, start);
  ASSERT_TRUE(why);
  const std::string link = model_.links[model_.spheres[c.sphere].link].name;
  EXPECT_TRUE(Has(*why, "arm sphere " + std::to_string(c.sphere) + " ")) << *why;
  EXPECT_TRUE(Has(*why, "on link '" + link + "'")) << *why;
  EXPECT_TRUE(Has(*why, "penetrates box 0 ")) << *why;
}

// Random arm configurations in an empty scene: each self collision names both spheres' links,
// each sphere below the chassis top says so.
TEST_F(StartTargetDiagnosisTest, SelfCollisionAndChassisNameTheSpheres) {
  Rng rng(7);
  int self_cases = 0, chassis_cases = 0;
  const Scene scene;
  const SceneClearanceChecker checker(kinematics_, scene);
  for (int i = 0; i < 5000 && (self_cases < 3 || chassis_cases < 3); ++i) {
    WholeBodyState state = testing::RandomState(model_, &rng);
    state.x_m = state.y_m = 0.0;
    const SceneClearance c = checker.Compute(state);
    if (c.self_m < 0.0) {
      const auto why = DiagnoseStartState(kinematics_, scene, state);
      ASSERT_TRUE(why);
      const auto [a, b] = model_.self_collision_pairs[c.self_pair];
      EXPECT_TRUE(Has(*why, "self collision")) << *why;
      EXPECT_TRUE(Has(*why, "arm sphere " + std::to_string(a) + " ")) << *why;
      EXPECT_TRUE(Has(*why, "arm sphere " + std::to_string(b) + " ")) << *why;
      EXPECT_TRUE(Has(*why, "overlap by")) << *why;
      ++self_cases;
    } else if (c.chassis_m < 0.0) {
      const auto why = DiagnoseStartState(kinematics_, scene, state);
      ASSERT_TRUE(why);
      EXPECT_TRUE(Has(*why, "arm sphere " + std::to_string(c.chassis_sphere) + " ")) << *why;
      EXPECT_TRUE(Has(*why, "below the chassis top")) << *why;
      ++chassis_cases;
    }
  }
  EXPECT_GE(self_cases, 3);
  EXPECT_GE(chassis_cases, 3);
}

TEST_F(StartTargetDiagnosisTest, ABaseOutsideTheSceneBoundsSaysSo) {
  const auto why = DiagnoseStartState(kinematics_, Scene{}, Stowed(12.0, 0.0));
  ASSERT_TRUE(why);
  EXPECT_TRUE(Has(*why, "outside the scene bounds")) << *why;
}

// A margin reports a near miss, which an exact check at 0 does not.
TEST_F(StartTargetDiagnosisTest, TheMarginReportsNearMisses) {
  Scene scene;
  scene.boxes.push_back(MakeBox({0.43, 0, 0.5}, {0.04, 0.5, 1}, 0.0));  // 0.01 m off
  EXPECT_EQ(DiagnoseStartState(kinematics_, scene, Stowed(0, 0)), std::nullopt);
  StartDiagnosisOptions options;
  options.obstacle_margin_m = 0.02;
  const auto why = DiagnoseStartState(kinematics_, scene, Stowed(0, 0), options);
  ASSERT_TRUE(why);
  EXPECT_TRUE(Has(*why, "is 0.010 m from box 0 ")) << *why;
}

Eigen::Isometry3d At(double x, double y, double z) {
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  X_WE.translation() = Eigen::Vector3d(x, y, z);
  return X_WE;
}

TEST(DiagnoseTargetTest, NamesTheFloorTheRoomAndTheBox) {
  Scene scene;  // bounds: [-10, 10]^2 x [0, 1.6] m
  scene.boxes.push_back(MakeBox({-3, 0, 0.5}, {1, 1, 1}, 0.0));
  scene.boxes.push_back(MakeBox({2, 2, 0.4}, {1, 1, 0.8}, 0.0));
  scene.boxes.push_back(MakeBox({2, 2, 0.2}, {0.5, 0.5, 0.4}, 0.0));  // inside box 1
  EXPECT_EQ(DiagnoseTarget(scene, At(1, 1, 0.5)), std::nullopt);

  const auto below = DiagnoseTarget(scene, At(1, 1, -0.05));
  ASSERT_TRUE(below);
  EXPECT_TRUE(Has(*below, "below the floor")) << *below;
  const auto outside = DiagnoseTarget(scene, At(11, 1, 0.5));
  ASSERT_TRUE(outside);
  EXPECT_TRUE(Has(*outside, "outside the room")) << *outside;
  const auto above = DiagnoseTarget(scene, At(1, 1, 2.0));
  ASSERT_TRUE(above);
  EXPECT_TRUE(Has(*above, "outside the room")) << *above;

  const auto inside = DiagnoseTarget(scene, At(2.1, 2, 0.3));
  ASSERT_TRUE(inside);
  EXPECT_TRUE(Has(*inside, "inside box 1 ")) << *inside;
  EXPECT_TRUE(Has(*inside, "0.300 m deep")) << *inside;  // to the bottom face, z = 0
  EXPECT_TRUE(Has(*inside, "1 more")) << *inside;

  Eigen::Isometry3d nan = At(1, 1, 0.5);
  nan.translation().x() = std::nan("");
  ASSERT_TRUE(DiagnoseTarget(scene, nan));
  EXPECT_TRUE(Has(*DiagnoseTarget(scene, nan), "not finite"));
  Eigen::Isometry3d skew = At(1, 1, 0.5);
  skew.linear()(0, 1) = 0.5;
  ASSERT_TRUE(DiagnoseTarget(scene, skew));
}

}  // namespace
}  // namespace topay
