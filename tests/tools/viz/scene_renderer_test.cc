#include "tools/viz/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "tools/viz/color_map.h"
#include "tools/viz/field_drawing.h"

namespace topay::viz {
namespace {

// A 10 x 10 m room with one grounded box at (-2, -2) and one floating cube at (2, 2).
Scene MakeScene() {
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
  OrientedBox grounded;
  grounded.center_W_m = {-2, -2, 0.5};
  grounded.size_m = {1.0, 0.6, 1.0};
  grounded.yaw_rad = 0.3;
  OrientedBox floating;
  floating.center_W_m = {2, 2, 0.8};
  floating.size_m = {0.8, 0.8, 0.4};
  scene.boxes = {grounded, floating};
  return scene;
}

Rgb PixelAt(const Image& image, const SceneRenderOptions& options, const Scene& scene,
            const Eigen::Vector2d& p_W) {
  const Eigen::Vector2d p_px = SceneMapView(scene, options).ToPixel(p_W);
  return image.At(static_cast<int>(p_px.x()), static_cast<int>(p_px.y()));
}

// Pixels in [x0, x1) x [y0, y1) that are darker than the paper (text, ticks).
int InkPixels(const Image& image, double x0, double y0, double x1, double y1) {
  int count = 0;
  for (int y = static_cast<int>(y0); y < static_cast<int>(y1); ++y) {
    for (int x = static_cast<int>(x0); x < static_cast<int>(x1); ++x) {
      if (RelativeLuminance(image.At(x, y)) < 0.5) ++count;
    }
  }
  return count;
}

TEST(SceneRendererTest, ObstacleCentreDiffersFromFarFreeSpace) {
  const Scene scene = MakeScene();
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene);
  SceneDrawing drawing;
  drawing.scene = &scene;
  drawing.base_field = &fields.base_field_2d;
  const SceneRenderOptions options;
  SceneRenderReport report;
  const Image image = RenderScene(drawing, options, &report);

  // The map block is 10.5 m at 40 px/m wide, right of the y axis; legends lie below.
  EXPECT_EQ(SceneMapView(scene, options).width_px(), 420);
  EXPECT_EQ(image.width(), SceneImageWidth(420, options));
  EXPECT_GT(image.width(), 420 + 40);
  EXPECT_GT(image.height(), 420 + 40);
  EXPECT_DOUBLE_EQ(report.map_px.x1 - report.map_px.x0, 420.0);

  const Rgb box_centre = PixelAt(image, options, scene, {-2, -2});
  const Eigen::Vector2d far_W(2, -2.5);  // >= 2 m from both boxes.
  const Rgb free_far = PixelAt(image, options, scene, far_W);
  // The grounded box shows its top-height grey, free space the field's colour there.
  EXPECT_EQ(box_centre, GreyRamp(ScalarRange{0.0, 1.6}.Normalize(1.0)));
  const Eigen::Vector2d far_px = SceneMapView(scene, options).ToPixel(far_W);
  const Eigen::Vector2d far_centre_W = SceneMapView(scene, options).ToWorld(
      Eigen::Vector2d(std::floor(far_px.x()) + 0.5, std::floor(far_px.y()) + 0.5));
  EXPECT_EQ(free_far, DistanceColour(fields.base_field_2d.Distance(far_centre_W),
                                     FieldValueRange(fields.base_field_2d)));
  EXPECT_NE(box_centre, free_far);
  // Close to the grounded box the field is darker (lower luminance) than far away.
  const Rgb near = PixelAt(image, options, scene, {-2, -1.2});
  EXPECT_LT(RelativeLuminance(near), RelativeLuminance(free_far));
  // The floating cube is above the base band: the field under it is free, and it is drawn
  // translucent, so its centre is neither opaque grey nor the bare field colour.
  const Rgb cube_centre = PixelAt(image, options, scene, {2.05, 1.95});
  EXPECT_NE(cube_centre, GreyRamp(1.0));
  EXPECT_NE(cube_centre, free_far);
}

TEST(SceneRendererTest, DrawsTheRobotAndTheTarget) {
  const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                          TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  const Scene scene = MakeScene();
  SceneDrawing drawing;
  drawing.scene = &scene;
  drawing.kinematics = &kinematics;
  WholeBodyState state;
  state.x_m = 2.0;
  state.y_m = -2.0;
  state.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  drawing.robots.push_back({state, colors::kStart, "start"});
  const SceneRenderOptions options;
  SceneDrawing scene_only;
  scene_only.scene = &scene;
  const Image without_robot = RenderScene(scene_only, options);
  const Image with_robot = RenderScene(drawing, options);
  // At q = 0 the arm stands upright: the top sphere covers the arm mount's xy, (0, 0.115) m
  // from the base origin in the base frame, drawn in the warm colour of its height.
  const Rgb at_arm = PixelAt(with_robot, options, scene, {2.0, -2.0 + 0.115});
  EXPECT_NE(at_arm, PixelAt(without_robot, options, scene, {2.0, -2.0 + 0.115}));
  EXPECT_GT(at_arm.r, at_arm.b);  // Warm ramp, not grey or viridis.
  // The chassis' white fill lightens the floor under its corner region.
  const Rgb in_chassis = PixelAt(with_robot, options, scene, {2.25, -2.2});
  EXPECT_GT(RelativeLuminance(in_chassis),
            RelativeLuminance(PixelAt(without_robot, options, scene, {2.25, -2.2})));
  // Far from the robot nothing changed.
  EXPECT_EQ(PixelAt(with_robot, options, scene, {-4, 4}),
            PixelAt(without_robot, options, scene, {-4, 4}));
}

TEST(SceneRendererTest, RejectsIncompleteInput) {
  EXPECT_THROW(RenderScene(SceneDrawing{}), std::invalid_argument);
  const Scene scene = MakeScene();
  SceneDrawing drawing;
  drawing.scene = &scene;
  drawing.robots.push_back({});  // No kinematics.
  EXPECT_THROW(RenderScene(drawing), std::invalid_argument);
}

TEST(SceneRendererTest, TheClearanceScaleSpansTheFieldsValuesAndHasALabelledBar) {
  const Scene scene = MakeScene();
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene);
  const SignedDistanceField2& field = fields.base_field_2d;
  SceneDrawing drawing;
  drawing.scene = &scene;
  drawing.base_field = &field;
  SceneRenderReport report;
  const Image image = RenderScene(drawing, {}, &report);

  // The field's own extremes, found here cell by cell.
  double lo = 1e9, hi = -1e9;
  for (int iy = 0; iy < field.geometry().dims.y(); ++iy) {
    for (int ix = 0; ix < field.geometry().dims.x(); ++ix) {
      lo = std::min(lo, static_cast<double>(field.CellValue(ix, iy)));
      hi = std::max(hi, static_cast<double>(field.CellValue(ix, iy)));
    }
  }
  ASSERT_LT(lo, 0.0);  // Inside the grounded box.
  ASSERT_GT(hi, 1.0);
  ASSERT_TRUE(report.field_range_m.has_value());
  EXPECT_DOUBLE_EQ(report.field_range_m->min, lo);
  EXPECT_DOUBLE_EQ(report.field_range_m->max, hi);
  // The colour bar: the map's low end at its left, high end at its right.
  ASSERT_TRUE(report.clearance_bar.has_value());
  const LegendBox bar = *report.clearance_bar;
  const int mid = static_cast<int>(0.5 * (bar.y0 + bar.y1));
  const double n = bar.x1 - bar.x0;
  EXPECT_EQ(image.At(static_cast<int>(bar.x0), mid), Viridis(0.5 / n));
  EXPECT_EQ(image.At(static_cast<int>(bar.x1) - 1, mid), Viridis(1.0 - 0.5 / n));
  // Its end labels ("-0.xx m", "x.xx m") are drawn beside it.
  EXPECT_GT(InkPixels(image, bar.x0 - 40, bar.y0, bar.x0 - 2, bar.y1), 10);
  EXPECT_GT(InkPixels(image, bar.x1 + 2, bar.y0, bar.x1 + 40, bar.y1), 10);
}

TEST(SceneRendererTest, TheMapHasMetricAxesWithLabels) {
  const Scene scene = MakeScene();
  SceneDrawing drawing;
  drawing.scene = &scene;
  const SceneRenderOptions options;
  SceneRenderReport report;
  const Image image = RenderScene(drawing, options, &report);
  const LegendBox& map = report.map_px;
  const MapTicks ticks = MapAxisTicks(SceneMapView(scene, options), options.axes);
  // 10.5 m over 420 px, a tick about every 60 px: every 2 m at -4..4 on both axes.
  EXPECT_DOUBLE_EQ(ticks.step_m, 2.0);
  ASSERT_EQ(ticks.x_m.size(), 5u);
  ASSERT_EQ(ticks.y_m.size(), 5u);
  EXPECT_DOUBLE_EQ(ticks.x_m.front(), -4.0);
  // Tick labels below the map and left of it (ink), plain paper in the corner between them.
  EXPECT_GT(InkPixels(image, map.x0, map.y1 + 6, map.x1, map.y1 + 22), 100);
  EXPECT_GT(InkPixels(image, map.x0 - 30, map.y0, map.x0 - 6, map.y1), 100);
  EXPECT_EQ(InkPixels(image, 0, map.y1 + 8, map.x0 - 20, map.y1 + 30), 0);
  // A tick mark under x = 0 m, none between ticks.
  const double u = SceneMapView(scene, options).ToPixel({0.0, 0.0}).x();
  EXPECT_GT(InkPixels(image, u - 1, map.y1 + 2, u + 1, map.y1 + 5), 0);
  const double between = SceneMapView(scene, options).ToPixel({1.0, 0.0}).x();
  EXPECT_EQ(InkPixels(image, between - 1, map.y1 + 2, between + 1, map.y1 + 5), 0);
}

TEST(FieldDrawingTest, ColourRunsFromTheLowEndToTheHighEndOfTheRange) {
  const ScalarRange range{-0.3, 2.0};
  EXPECT_EQ(DistanceColour(-0.3, range), Viridis(0.0));
  EXPECT_EQ(DistanceColour(2.0, range), Viridis(1.0));
  EXPECT_EQ(DistanceColour(5.0, range), Viridis(1.0));
  EXPECT_LT(RelativeLuminance(DistanceColour(0.5, range)),
            RelativeLuminance(DistanceColour(1.5, range)));
  // A fixed range given in the options wins over the field's own.
  FieldDrawingOptions options;
  options.range_m = ScalarRange{0.0, 1.0};
  const Scene scene = MakeScene();
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene);
  EXPECT_DOUBLE_EQ(DistanceColourRange(fields.base_field_2d, options).max, 1.0);
  EXPECT_NE(DistanceColourRange(fields.base_field_2d).max, 1.0);
}

}  // namespace
}  // namespace topay::viz
