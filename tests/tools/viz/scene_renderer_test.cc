#include "tools/viz/scene_renderer.h"

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
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(options.margin_m);
  const ViewTransform view(Eigen::AlignedBox2d(scene.bounds_W_m.min().head<2>() - margin,
                                               scene.bounds_W_m.max().head<2>() + margin),
                           options.px_per_m);
  const Eigen::Vector2d p_px = view.ToPixel(p_W);
  return image.At(static_cast<int>(p_px.x()), static_cast<int>(p_px.y()));
}

TEST(SceneRendererTest, ObstacleCentreDiffersFromFarFreeSpace) {
  const Scene scene = MakeScene();
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene);
  SceneDrawing drawing;
  drawing.scene = &scene;
  drawing.base_field = &fields.base_field_2d;
  const SceneRenderOptions options;
  const Image image = RenderScene(drawing, options);

  // The map block is 10.5 m at 40 px/m wide; a legend strip lies below it.
  EXPECT_EQ(image.width(), 420);
  EXPECT_GT(image.height(), 420);

  const Rgb box_centre = PixelAt(image, options, scene, {-2, -2});
  const Rgb free_far = PixelAt(image, options, scene, {2, -2.5});  // >= 2 m from both boxes.
  // The grounded box shows its top-height grey, free space the clipped end of the map.
  EXPECT_EQ(box_centre, GreyRamp(ScalarRange{0.0, 1.6}.Normalize(1.0)));
  EXPECT_EQ(free_far, Viridis(1.0));
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

TEST(FieldDrawingTest, ColourIsDarkestInsideAndClippedFarAway) {
  const FieldDrawingOptions options{2.0};
  EXPECT_EQ(DistanceColour(-0.3, options), colors::kObstacleCore);
  EXPECT_EQ(DistanceColour(std::nan(""), options), colors::kObstacleCore);
  EXPECT_EQ(DistanceColour(5.0, options), Viridis(1.0));
  EXPECT_LT(RelativeLuminance(colors::kObstacleCore), RelativeLuminance(DistanceColour(0.01)));
  EXPECT_LT(RelativeLuminance(DistanceColour(0.5)), RelativeLuminance(DistanceColour(1.5)));
}

}  // namespace
}  // namespace topay::viz
