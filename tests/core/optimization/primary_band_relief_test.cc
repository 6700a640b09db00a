// The endpoint relief and the 2D field's primary band (SignedDistanceField::primary_band): a
// start under a low table top is relieved of the table top's shadow, not of the obstacles the
// base cylinder itself can touch.
#include <cmath>

#include <gtest/gtest.h>

#include "core/map/scene_distance_fields.h"
#include "core/optimization/endpoint_relief.h"
#include "core/optimization/sample_penalties.h"
#include "core/planning/planner_fields.h"
#include "tests/common/make_box.h"
#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

PenaltyMask OnlyBaseObstacle() {
  PenaltyMask mask = NoPenalties();
  mask[static_cast<int>(PenaltyTerm::kBaseObstacle)] = true;
  return mask;
}

class PrimaryBandReliefTest : public ::testing::Test {
 protected:
  PrimaryBandReliefTest()
      : model_(testing::LoadTopayModel()),
        kinematics_(model_),
        scene_(MakeScene()),
        fields_(BuildSceneDistanceFields(scene_, PlannerFieldOptions(kinematics_))) {}

  static Scene MakeScene() {
    Scene scene;
    scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6));
    scene.boxes.push_back(MakeBox({0.0, 0.0, 0.5}, {2.0, 2.0, 0.04}));  // low table top
    scene.boxes.push_back(MakeBox({1.2, 0.0, 0.4}, {0.4, 0.6, 0.8}));   // face at x = 1.0
    return scene;
  }

  RobotModel model_;
  Kinematics kinematics_;
  Scene scene_;
  SceneDistanceFields fields_;
};

TEST_F(PrimaryBandReliefTest, TheFieldKeepsItsPrimaryBand) {
  const SignedDistanceField2* primary = fields_.base_field_2d.primary_band();
  ASSERT_NE(primary, nullptr);
  // Under the table top: deep in the lowered band, 1 m from the grounded box on the primary.
  EXPECT_LT(fields_.base_field_2d.Distance(Eigen::Vector2d(0.0, 0.0)), 0.0);
  EXPECT_NEAR(primary->Distance(Eigen::Vector2d(0.0, 0.0)), 1.0, 0.01);
  // The lowered field is never above its primary band.
  for (double x = -2.0; x <= 2.0; x += 0.13) {
    for (double y = -2.0; y <= 2.0; y += 0.17) {
      EXPECT_LE(fields_.base_field_2d.Distance(Eigen::Vector2d(x, y)),
                primary->Distance(Eigen::Vector2d(x, y)) + 1e-6);
    }
  }
}

TEST_F(PrimaryBandReliefTest, DeficitOfAStartUnderTheTableIsTheShadowsOnly) {
  SamplePenalties penalties(kinematics_, fields_.base_field_2d, fields_.field_3d, BaseLimits{},
                            SamplePenaltyOptions());
  const WholeBodyState start = testing::MakeState(0.0, 0.0, 0.0, testing::ReadyJoints());
  const ClearanceDeficit deficit = ComputeClearanceDeficit(penalties, start, 0.0);
  EXPECT_GT(deficit.base_m, penalties.base_threshold_m());  // inside the shadow
  EXPECT_EQ(deficit.base_primary_m, 0.0);                   // the box is 1 m away
  // Near the grounded box the start falls short on the primary band too.
  const WholeBodyState near_box = testing::MakeState(0.6, 0.0, 0.0, testing::ReadyJoints());
  const ClearanceDeficit near = ComputeClearanceDeficit(penalties, near_box, 0.0);
  EXPECT_GT(near.base_primary_m, 0.0);
  EXPECT_LE(near.base_primary_m, near.base_m);
}

// Relieved by the start's deficit (the whole shadow), a sample 0.25 m from the grounded box
// is still penalised, on the primary band, with a gradient that matches central differences.
TEST_F(PrimaryBandReliefTest, RelievedSamplesKeepTheirMarginToWhatTheBaseTouches) {
  SamplePenalties penalties(kinematics_, fields_.base_field_2d, fields_.field_3d, BaseLimits{},
                            SamplePenaltyOptions());
  penalties.set_enabled(OnlyBaseObstacle());
  const WholeBodyState start = testing::MakeState(0.0, 0.0, 0.0, testing::ReadyJoints());
  EndpointRelief relief;
  relief.SetStart(ComputeClearanceDeficit(penalties, start, 0.0), 0.5);
  penalties.set_endpoint_relief(&relief);
  const double u = 0.1;  // full weight

  SampleQuantities sample = penalties.MakeQuantities();
  sample.q_rad = testing::ReadyJoints();
  sample.x_m = 0.7512;
  sample.y_m = 0.0231;
  const Eigen::Vector2d p(sample.x_m, sample.y_m);
  // The lowered field's requirement alone is met thanks to the relief...
  EXPECT_LT(penalties.base_threshold_m() - relief.base_m(u) - fields_.base_field_2d.Distance(p),
            0.0);
  // ...but the primary band's is not.
  SampleQuantities gradient = penalties.MakeQuantities();
  const double value = penalties.Evaluate(sample, u, &gradient);
  EXPECT_GT(value, 0.0);
  EXPECT_GT(gradient.x_m, 0.0);  // moving towards the box (+x) raises P
  constexpr double kStep = 1e-6;
  for (double* coordinate : {&sample.x_m, &sample.y_m}) {
    const double original = *coordinate;
    *coordinate = original + kStep;
    const double plus = penalties.Evaluate(sample, u, nullptr);
    *coordinate = original - kStep;
    const double minus = penalties.Evaluate(sample, u, nullptr);
    *coordinate = original;
    const double numeric = (plus - minus) / (2.0 * kStep);
    const double analytic = coordinate == &sample.x_m ? gradient.x_m : gradient.y_m;
    EXPECT_NEAR(analytic, numeric, 1e-6 * std::max(1.0, std::abs(numeric)) + 1e-4);
  }
  // Beyond the ramp (no relief) the lowered field decides alone, as before.
  EXPECT_EQ(relief.base_m(1.0), 0.0);
}

}  // namespace
}  // namespace topay
