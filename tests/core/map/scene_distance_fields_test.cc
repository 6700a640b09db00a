#include "core/map/scene_distance_fields.h"
#include "tests/common/make_box.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/random.h"
#include "tests/core/map/random_room.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

// A 1 x 1 m table, top [0.70, 0.75] m, four 0.05 m legs at the corners, in a 4 x 4 m room.
Scene TableScene() {
  Scene scene;
  scene.kind = "table";
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1.6));
  scene.boxes.push_back(MakeBox({0, 0, 0.725}, {1.0, 1.0, 0.05}));
  for (double x : {-0.475, 0.475}) {
    for (double y : {-0.475, 0.475}) scene.boxes.push_back(MakeBox({x, y, 0.35}, {0.05, 0.05, 0.7}));
  }
  return scene;
}

TEST(SceneDistanceFieldsTest, BasePassesUnderTheTableTopWhichTheArmMustClear) {
  const SceneDistanceFields fields = BuildSceneDistanceFields(TableScene());
  // 3D: the top is an obstacle: at its middle, the field is about zero (within one cell), and
  // 0.3 m above it about 0.3 m.
  EXPECT_NEAR(fields.field_3d.Distance(Eigen::Vector3d(0, 0, 0.725)), 0.0, 0.1);
  EXPECT_NEAR(fields.field_3d.Distance(Eigen::Vector3d(0, 0, 1.05)), 0.3, 0.1);
  // 3D: the legs too.
  EXPECT_NEAR(fields.field_3d.Distance(Eigen::Vector3d(0.475, 0.475, 0.3)), 0.0, 0.1);
  // 2D: under the top's middle the base sees only the legs, 0.45 * sqrt(2) = 0.636 m away.
  EXPECT_NEAR(fields.base_field_2d.Distance(Eigen::Vector2d(0, 0)), 0.45 * std::sqrt(2.0), 0.1);
  EXPECT_NEAR(fields.base_field_2d.Distance(Eigen::Vector2d(0.475, 0.475)), 0.0, 0.1);
  // Far from the table in 2D.
  EXPECT_GT(fields.base_field_2d.Distance(Eigen::Vector2d(-1.5, 1.5)), 1.2);

  const SceneDistanceFieldsSummary& summary = fields.summary;
  EXPECT_EQ(summary.num_boxes_in_base_band, 4);
  EXPECT_EQ(summary.num_cells_3d, 40 * 40 * 16);
  EXPECT_EQ(summary.num_cells_2d, 40 * 40);
  // Legs: 1 to 4 columns each, 2D and 7 layers in 3D; top: 10 x 10 to 11 x 11 cells, 1 layer.
  EXPECT_GE(summary.num_occupied_2d, 4);
  EXPECT_LE(summary.num_occupied_2d, 16);
  EXPECT_GE(summary.num_occupied_3d, 100 + 4 * 7);
  EXPECT_LE(summary.num_occupied_3d, 121 + 16 * 7);
  EXPECT_GE(summary.rasterize_3d_s, 0.0);
  EXPECT_GE(summary.total_s,
            summary.rasterize_3d_s + summary.build_3d_s + summary.rasterize_2d_s +
                summary.build_2d_s);
}

TEST(SceneDistanceFieldsTest, OptionsSetResolutionBandAndBounds) {
  SceneDistanceFieldsOptions options;
  options.resolution_m = 0.05;
  options.base_band = HeightBand{0.0, 1.0};  // a band that reaches the table top
  options.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 1));
  const SceneDistanceFields fields = BuildSceneDistanceFields(TableScene(), options);
  EXPECT_EQ(fields.field_3d.geometry().dims, Eigen::Vector3i(40, 40, 20));
  EXPECT_EQ(fields.summary.num_boxes_in_base_band, 5);
  EXPECT_LT(fields.base_field_2d.Distance(Eigen::Vector2d(0, 0)), 0.0);  // under the top now
}

TEST(SceneDistanceFieldsTest, BaseFieldHasItsOwnResolution) {
  SceneDistanceFieldsOptions options;
  options.resolution_m = 0.1;
  options.base_resolution_m = 0.05;
  const SceneDistanceFields fields = BuildSceneDistanceFields(TableScene(), options);
  // 3D field unchanged; the 2D grid covers the same 4 x 4 m at 0.05 m.
  EXPECT_EQ(fields.field_3d.geometry().resolution_m, 0.1);
  EXPECT_EQ(fields.field_3d.geometry().dims, Eigen::Vector3i(40, 40, 16));
  const GridGeometry2& base = fields.base_field_2d.geometry();
  EXPECT_EQ(base.resolution_m, 0.05);
  EXPECT_EQ(base.dims, Eigen::Vector2i(80, 80));
  EXPECT_TRUE(base.origin_W_m.isApprox(Eigen::Vector2d(-2, -2)));
  EXPECT_EQ(fields.summary.num_cells_2d, 80 * 80);
  EXPECT_EQ(fields.summary.num_cells_3d, 40 * 40 * 16);
  // Legs (0.05 m, centred on x, y = +-0.475 m): 1 to 4 cells each at 0.05 m.
  EXPECT_GE(fields.summary.num_occupied_2d, 4);
  EXPECT_LE(fields.summary.num_occupied_2d, 16);

  // Default (0): the 2D grid is the 3D grid's footprint.
  const SceneDistanceFields same = BuildSceneDistanceFields(TableScene());
  EXPECT_EQ(same.base_field_2d.geometry().resolution_m, 0.1);
  EXPECT_EQ(same.base_field_2d.geometry().dims, Eigen::Vector2i(40, 40));
}

// The finer base field against exact 2D distances to the footprints of the boxes in the base
// band, on 5,000 random points of a 10 x 10 m room: within one of its (0.05 m) cells.
TEST(SceneDistanceFieldsTest, FinerBaseFieldIsWithinOneOfItsCellsOfExactFootprintDistance) {
  const Scene scene = testing::RandomDisjointRoom(7, 10.0, 60, 0.15);
  SceneDistanceFieldsOptions options;
  options.base_resolution_m = 0.05;
  std::vector<OrientedBox> in_band;
  for (const OrientedBox& box : scene.boxes) {
    const double half = 0.5 * box.size_m.z();
    if (box.center_W_m.z() - half < options.base_band.z_max_m &&
        box.center_W_m.z() + half > options.base_band.z_min_m) {
      in_band.push_back(box);
    }
  }
  ASSERT_GT(in_band.size(), 10u);
  ASSERT_LT(in_band.size(), scene.boxes.size());  // floating boxes and slabs are left out
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene, options);
  ASSERT_EQ(fields.base_field_2d.geometry().resolution_m, 0.05);
  EXPECT_EQ(fields.summary.num_boxes_in_base_band, static_cast<int>(in_band.size()));
  Rng rng(11);
  double max_error_m = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector2d p(rng.Uniform(-5, 5), rng.Uniform(-5, 5));
    const double error_m =
        std::abs(fields.base_field_2d.Distance(p) - testing::ExactSignedDistance2d(in_band, p));
    max_error_m = std::max(max_error_m, error_m);
  }
  std::cout << "2D base field at 0.05 m: max error " << max_error_m << " m\n";
  EXPECT_LE(max_error_m, 0.05);
}

TEST(SceneDistanceFieldsTest, BadInputIsReportedClearly) {
  SceneDistanceFieldsOptions options;
  options.resolution_m = 0.0;
  EXPECT_THROW(BuildSceneDistanceFields(TableScene(), options), std::invalid_argument);
  options = {};
  options.base_band = HeightBand{0.2, 0.1};
  EXPECT_THROW(BuildSceneDistanceFields(TableScene(), options), std::invalid_argument);
  options = {};
  options.field.zero_level_inset_cells = -1.0;
  EXPECT_THROW(BuildSceneDistanceFields(TableScene(), options), std::invalid_argument);
  for (double bad_resolution : {-0.05, std::nan(""), HUGE_VAL}) {
    options = {};
    options.base_resolution_m = bad_resolution;
    try {
      BuildSceneDistanceFields(TableScene(), options);
      FAIL() << "expected std::invalid_argument for base_resolution_m " << bad_resolution;
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("base_resolution_m"), std::string::npos)
          << error.what();
    }
  }
  Scene bad = TableScene();
  bad.boxes[2].size_m.y() = std::nan("");
  try {
    BuildSceneDistanceFields(bad);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("scene box 2"), std::string::npos) << error.what();
  }
}

TEST(SceneDistanceFieldsTest, UpperBandCountsWithItsOffset) {
  // The table of TableScene, top at [0.70, 0.75] m: with an upper band up to 0.8 m and an
  // offset of 0.2 m, the base field under the top's middle drops from the legs' 0.636 m to
  // about -0.5 + 0.2 = -0.3 m (0.5 m deep inside the top's footprint).
  SceneDistanceFieldsOptions options;
  options.base_upper_band = HeightBand{0.0, 0.8};
  options.base_upper_band_offset_m = 0.2;
  const SceneDistanceFields fields = BuildSceneDistanceFields(TableScene(), options);
  EXPECT_NEAR(fields.base_field_2d.Distance(Eigen::Vector2d(0, 0)), -0.3, 0.1);
  // 1 m from the top's edge: min(1.0 + 0.2 upper, legs farther) = 1.2 m.
  EXPECT_NEAR(fields.base_field_2d.Distance(Eigen::Vector2d(-1.5, 0)), 1.0 + 0.2, 0.1);
  EXPECT_EQ(fields.summary.num_boxes_in_base_band, 4);
  EXPECT_EQ(fields.summary.num_boxes_in_upper_band, 5);
  // An upper band below the top changes nothing but the count.
  options.base_upper_band = HeightBand{0.0, 0.6};
  const SceneDistanceFields low = BuildSceneDistanceFields(TableScene(), options);
  EXPECT_NEAR(low.base_field_2d.Distance(Eigen::Vector2d(0, 0)), 0.45 * std::sqrt(2.0), 0.1);
  EXPECT_EQ(low.summary.num_boxes_in_upper_band, 4);
}

// base_exact_cap_m: exact footprint distances at the cell centres (both bands), half the EDT
// field's exactness margin, and the offset band declared for the rigid spheres.
TEST(SceneDistanceFieldsTest, ExactBaseFieldHoldsFootprintDistances) {
  SceneDistanceFieldsOptions options;
  options.base_resolution_m = 0.02;
  options.base_upper_band = HeightBand{0.0, 0.8};
  options.base_upper_band_offset_m = 0.2;
  const SceneDistanceFields edt = BuildSceneDistanceFields(TableScene(), options);
  options.base_exact_cap_m = 1.0;
  const SceneDistanceFields exact = BuildSceneDistanceFields(TableScene(), options);
  EXPECT_NEAR(edt.base_field_2d.exactness_margin_m(), std::sqrt(2.0) * 0.02, 1e-12);
  EXPECT_NEAR(exact.base_field_2d.exactness_margin_m(), 0.02 / std::sqrt(2.0), 1e-12);
  for (const SceneDistanceFields* fields : {&edt, &exact}) {
    ASSERT_TRUE(fields->base_field_2d.offset_band().has_value());
    EXPECT_EQ(fields->base_field_2d.offset_band()->offset_m, 0.2);
    EXPECT_EQ(fields->base_field_2d.offset_band()->band.z_max_m, 0.8);
  }
  EXPECT_EQ(exact.summary.num_boxes_in_base_band, 4);
  EXPECT_EQ(exact.summary.num_boxes_in_upper_band, 5);
  // 1 m from the top's edge (x = -1.5): upper band 1.0 + 0.2, capped at 1.0.
  EXPECT_NEAR(exact.base_field_2d.Distance(Eigen::Vector2d(-1.5, 0)), 1.0, 1e-6);
  // 0.3 m from the top's edge: 0.3 + 0.2 exactly (the legs are farther).
  EXPECT_NEAR(exact.base_field_2d.Distance(Eigen::Vector2d(-0.8, 0)), 0.5, 1e-5);
  options.base_exact_cap_m = -1.0;
  EXPECT_THROW(BuildSceneDistanceFields(TableScene(), options), std::invalid_argument);
  // Without an upper band there is no offset band.
  EXPECT_FALSE(BuildSceneDistanceFields(TableScene(), {}).base_field_2d.offset_band().has_value());
}

// arm_exact_cap_m: exact box distances at the 3D cell centres, half the EDT field's margin;
// the same occupied cells counted; a bad cap refused naming it.
TEST(SceneDistanceFieldsTest, ExactArmFieldHoldsBoxDistances) {
  SceneDistanceFieldsOptions options;
  options.resolution_m = 0.05;
  const SceneDistanceFields edt = BuildSceneDistanceFields(TableScene(), options);
  EXPECT_DOUBLE_EQ(ArmFieldMargin(options), edt.field_3d.exactness_margin_m());
  options.arm_exact_cap_m = 1.0;
  const SceneDistanceFields exact = BuildSceneDistanceFields(TableScene(), options);
  EXPECT_DOUBLE_EQ(ArmFieldMargin(options), exact.field_3d.exactness_margin_m());
  EXPECT_NEAR(edt.field_3d.exactness_margin_m(), std::sqrt(3.0) * 0.05, 1e-12);
  EXPECT_NEAR(exact.field_3d.exactness_margin_m(), 0.5 * std::sqrt(3.0) * 0.05, 1e-12);
  EXPECT_GT(exact.summary.num_occupied_3d, 0);
  // Under the top (bottom face at 0.70 m), above the floor's middle: 0.2 m exactly (the legs
  // are farther), within the margin of the interpolant.
  const Eigen::Vector3d p_W(0.0, 0.0, 0.5);
  EXPECT_NEAR(exact.field_3d.Distance(p_W), 0.2, exact.field_3d.exactness_margin_m());
  EXPECT_LE(exact.field_3d.Distance(p_W), 0.2 + exact.field_3d.exactness_margin_m());
  // Far from everything: the cap.
  EXPECT_NEAR(exact.field_3d.Distance(Eigen::Vector3d(-1.8, -1.8, 1.5)), 1.0, 1e-6);
  options.arm_exact_cap_m = -1.0;
  try {
    BuildSceneDistanceFields(TableScene(), options);
    FAIL() << "a negative cap was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("arm_exact_cap_m"), std::string::npos) << e.what();
  }
}

TEST(SceneDistanceFieldsTest, BadUpperBandIsReportedClearly) {
  SceneDistanceFieldsOptions options;
  options.base_upper_band = HeightBand{0.5, 0.2};
  try {
    BuildSceneDistanceFields(TableScene(), options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("base_upper_band"), std::string::npos) << error.what();
  }
  options.base_upper_band = HeightBand{0.0, 0.8};
  options.base_upper_band_offset_m = -0.1;
  try {
    BuildSceneDistanceFields(TableScene(), options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("base_upper_band_offset_m"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace topay
