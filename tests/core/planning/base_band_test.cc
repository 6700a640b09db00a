#include "core/planning/base_band.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"

namespace topay {
namespace {

class BaseBandTest : public ::testing::Test {
 protected:
  BaseBandTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}
  RobotModel model_;
  Kinematics kinematics_;
};

// The authors' code's robot: chassis top 0.155 m; the arm is mounted at (0, 0.115) and its two
// link-1 spheres (0.220 and 0.310 m, r 0.06) and the shoulder sphere (0.4115 m, r 0.08) lie on
// joint 1's axis, so no joint moves them: top 0.4915 m, reach 0.115 + 0.08 = 0.195 m.
TEST_F(BaseBandTest, RigidLowerBodyOfTheTopayArm) {
  const RigidLowerBody body = RigidLowerBodyOf(kinematics_);
  EXPECT_NEAR(body.chassis_top_m, 0.155, 1e-9);
  EXPECT_NEAR(body.top_m, 0.4115 + 0.08, 1e-6);
  EXPECT_NEAR(body.sphere_reach_m, 0.115 + 0.08, 1e-6);
}

TEST_F(BaseBandTest, FrontEndBaseBandAddsTheArmMargin) {
  const HeightBand band = FrontEndBaseBand(kinematics_, 0.1);
  EXPECT_EQ(band.z_min_m, 0.0);
  EXPECT_NEAR(band.z_max_m, 0.4915 + 0.1, 1e-6);
  EXPECT_NEAR(FrontEndBaseBand(kinematics_, -1.0).z_max_m, 0.4915, 1e-6);  // negative: none
}

TEST_F(BaseBandTest, PlannerFieldOptionsUseTwoBands) {
  const SceneDistanceFieldsOptions options = PlannerFieldOptions(kinematics_);
  // The exact 3D field's margin (BuildBoxDistanceField), half an EDT field's.
  const double arm_margin_m = 0.5 * std::sqrt(3.0) * 0.05;
  EXPECT_EQ(options.resolution_m, 0.05);
  EXPECT_GT(options.arm_exact_cap_m, 0.08 + 0.3 + arm_margin_m);  // sphere + saturation
  EXPECT_EQ(options.base_resolution_m, 0.01);
  EXPECT_NEAR(options.base_band.z_max_m, 0.155, 1e-9);
  ASSERT_TRUE(options.base_upper_band.has_value());
  EXPECT_NEAR(options.base_upper_band->z_max_m, 0.4915 + arm_margin_m, 1e-6);
  // The rigid spheres are checked by the upper band exactly: no 3D margin in the offset.
  EXPECT_NEAR(options.base_upper_band_offset_m, 0.40 - 0.195, 1e-6);
  EXPECT_GT(options.base_exact_cap_m, 0.40 + 0.1 + 0.02);  // above the PRM's requirement
}

TEST_F(BaseBandTest, RigidSpheresAreListedWithTheirExtent) {
  const RigidLowerBody body = RigidLowerBodyOf(kinematics_);
  ASSERT_EQ(body.spheres.size(), 3u);  // link 1's two spheres and the shoulder's
  EXPECT_EQ(body.spheres[0].index, 0);
  EXPECT_EQ(body.spheres[2].index, 2);
  EXPECT_NEAR(body.spheres[2].top_m, 0.4915, 1e-6);
  EXPECT_NEAR(body.spheres[0].bottom_m, 0.220 - 0.06, 1e-6);
  EXPECT_NEAR(body.spheres[2].reach_m, 0.195, 1e-6);
}

TEST_F(BaseBandTest, ArmFieldSkipsOnlyTheRigidSpheresTheBaseFieldCovers) {
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1.6));
  const int num_spheres = static_cast<int>(model_.spheres.size());
  // No offset band (chassis band only): every sphere goes to the 3D field.
  const SceneDistanceFields chassis_only = BuildSceneDistanceFields(scene, {});
  EXPECT_EQ(SpheresToCheckOnArmField(kinematics_, chassis_only.base_field_2d).size(),
            static_cast<std::size_t>(num_spheres));
  // The planner's fields: the three rigid spheres are covered.
  const SceneDistanceFields planner = BuildSceneDistanceFields(scene, PlannerFieldOptions(kinematics_));
  const std::vector<int> checked = SpheresToCheckOnArmField(kinematics_, planner.base_field_2d);
  ASSERT_EQ(checked.size(), static_cast<std::size_t>(num_spheres - 3));
  EXPECT_EQ(checked.front(), 3);
  // An offset too large for the shoulder's reach (0.40 - 0.21 = 0.19 < 0.195 m) or a band
  // below its top keeps it on the 3D field.
  SceneDistanceFieldsOptions options = PlannerFieldOptions(kinematics_);
  options.base_upper_band_offset_m = 0.21;
  EXPECT_EQ(SpheresToCheckOnArmField(kinematics_, BuildSceneDistanceFields(scene, options).base_field_2d)
                .front(),
            2);
  options = PlannerFieldOptions(kinematics_);
  options.base_upper_band->z_max_m = 0.45;
  EXPECT_EQ(SpheresToCheckOnArmField(kinematics_, BuildSceneDistanceFields(scene, options).base_field_2d)
                .front(),
            2);
}

}  // namespace
}  // namespace topay
