#include "core/planning/base_band.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
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

// The facts sheet's robot: chassis top 0.155 m; the arm is mounted at (0, 0.115) and its two
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
  const double arm_margin_m = std::sqrt(3.0) * 0.05;
  EXPECT_EQ(options.resolution_m, 0.05);
  EXPECT_EQ(options.base_resolution_m, 0.02);
  EXPECT_NEAR(options.base_band.z_max_m, 0.155, 1e-9);
  ASSERT_TRUE(options.base_upper_band.has_value());
  EXPECT_NEAR(options.base_upper_band->z_max_m, 0.4915 + arm_margin_m, 1e-6);
  EXPECT_NEAR(options.base_upper_band_offset_m, 0.40 - (0.195 + arm_margin_m), 1e-6);
}

}  // namespace
}  // namespace topay
