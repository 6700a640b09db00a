#include "tools/viz/trajectory_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "tests/common/make_box.h"
#include "tests/core/validate/rest_to_rest_motion.h"

namespace topay::viz {
namespace {

class TrajectoryViewTest : public ::testing::Test {
 protected:
  TrajectoryViewTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        scene_(MakeScene()),
        fields_(BuildSceneDistanceFields(scene_)),
        trajectory_(model_.num_joints(), 1, {}) {
    topay::testing::RestToRest motion;
    motion.p0_W = Eigen::Vector2d(-3.0, -2.0);
    motion.s_f_m = 6.0;
    motion.q0_rad = Eigen::VectorXd::Zero(model_.num_joints());
    motion.q_f_rad = motion.q0_rad;
    motion.duration_s = 8.0;
    topay::testing::UpdateRestToRest(motion, &trajectory_);
    start_.x_m = -3.0;
    start_.y_m = -2.0;
    start_.q_rad = motion.q0_rad;
    X_WE_.translation() = Eigen::Vector3d(3.5, -2.0, 0.8);
  }

  // A 10 x 10 m room with one box in its upper left quarter.
  static Scene MakeScene() {
    Scene scene;
    scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(-3.5, 3.5, 0.5), Eigen::Vector3d(1, 1, 1)));
    return scene;
  }

  TrajectoryView View(bool with_trajectory) const {
    TrajectoryView view;
    view.scene = &scene_;
    view.base_field = &fields_.base_field_2d;
    view.kinematics = &kinematics_;
    view.start = start_;
    view.X_WE_goal = X_WE_;
    view.trajectory = with_trajectory ? &trajectory_ : nullptr;
    view.title_lines = {"test room"};
    return view;
  }

  // What topay-scene draws for the same scene, target and title.
  Image SceneOnly(const SceneRenderOptions& options) const {
    SceneDrawing drawing;
    drawing.scene = &scene_;
    drawing.base_field = &fields_.base_field_2d;
    drawing.targets.push_back({X_WE_, colors::kTarget, "end-effector target"});
    drawing.title_lines = {"test room"};
    return RenderScene(drawing, options);
  }

  RobotModel model_;
  Kinematics kinematics_;
  Scene scene_;
  SceneDistanceFields fields_;
  ArcYawTrajectory trajectory_;
  WholeBodyState start_;
  Eigen::Isometry3d X_WE_ = Eigen::Isometry3d::Identity();
};

TEST_F(TrajectoryViewTest, TheSceneIsDrawnAsTopayScene) {
  const TrajectoryViewOptions options;
  const Image image = RenderTrajectoryView(View(true), options);
  const Image scene = SceneOnly(options.scene);
  const ViewTransform map = SceneMapView(scene_, options.scene);
  ASSERT_EQ(image.width(), scene.width());
  ASSERT_GT(image.height(), scene.height());  // the trajectory legend row below
  // The axes and RenderScene's legend rows are the same (the last few rows of the scene's
  // image are its bottom padding, where the trajectory keys begin).
  const int map_top = static_cast<int>(map.offset_px().y());
  const int map_bottom = map_top + map.height_px();
  for (int y = map_bottom; y < scene.height() - 8; ++y) {
    for (int x = 0; x < scene.width(); ++x) {
      ASSERT_EQ(image.At(x, y), scene.At(x, y)) << x << ", " << y;
    }
  }
  // Away from the trajectory layer the map is RenderScene's, pixel for pixel.
  int compared = 0;
  const int map_left = static_cast<int>(map.offset_px().x());
  for (int y = map_top; y < map_bottom; y += 3) {
    for (int x = map_left; x < map_left + map.width_px(); x += 3) {
      const Eigen::Vector2d p_W = map.ToWorld({x + 0.5, y + 0.5});
      if (p_W.y() < 0.0 || p_W.x() > 2.0) continue;  // path at y = -2, target at x = 3.5
      ASSERT_EQ(image.At(x, y), scene.At(x, y)) << x << ", " << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 3000);
}

TEST_F(TrajectoryViewTest, DrawsThePathThePosesAndTheTarget) {
  const TrajectoryViewOptions options;
  const Image image = RenderTrajectoryView(View(true), options);
  const Image scene = SceneOnly(options.scene);
  const ViewTransform map = SceneMapView(scene_, options.scene);
  auto at = [&](const Image& im, const Eigen::Vector2d& p_W) {
    const Eigen::Vector2d p = map.ToPixel(p_W);
    return im.At(static_cast<int>(p.x()), static_cast<int>(p.y()));
  };
  // The base path between the footprints at 3 s (x = -1.43 m) and 4 s (x = 0): at 3.5 s,
  // x = -0.69 m, farther than the chassis' half diagonal (0.45 m) from both.
  const double x_mid = -3.0 + 6.0 * topay::testing::Ramp(3.5 / 8.0);
  EXPECT_EQ(at(image, {x_mid, -2.0}), options.trajectory.path_colour);
  EXPECT_NE(at(scene, {x_mid, -2.0}), options.trajectory.path_colour);
  // The start pose's base circle (radius 0.40 m) in the start colour, the end pose's in the
  // end colour: look for them on a ring around each base position.
  auto ring_has = [&](const Eigen::Vector2d& centre_W, const Rgb& colour) {
    for (int k = 0; k < 360; ++k) {
      const double a = k * M_PI / 180.0;
      for (double r : {0.39, 0.40, 0.41}) {
        if (at(image, centre_W + r * Eigen::Vector2d(std::cos(a), std::sin(a))) == colour) {
          return true;
        }
      }
    }
    return false;
  };
  EXPECT_TRUE(ring_has({-3.0, -2.0}, colors::kStart));
  EXPECT_TRUE(ring_has({3.0, -2.0}, colors::kGoal));
  EXPECT_FALSE(ring_has({0.0, 3.0}, colors::kStart));  // nothing drawn up there
}

TEST_F(TrajectoryViewTest, AFailedPlanShowsTheStartAndTheTargetOnly) {
  const TrajectoryViewOptions options;
  const Image failed = RenderTrajectoryView(View(false), options);
  const Image planned = RenderTrajectoryView(View(true), options);
  EXPECT_EQ(failed.width(), planned.width());
  EXPECT_LT(failed.height(), planned.height());  // fewer legend keys
  const ViewTransform map = SceneMapView(scene_, options.scene);
  const double x_mid = -3.0 + 6.0 * topay::testing::Ramp(3.5 / 8.0);
  const Eigen::Vector2d p = map.ToPixel({x_mid, -2.0});
  EXPECT_NE(failed.At(static_cast<int>(p.x()), static_cast<int>(p.y())),
            options.trajectory.path_colour);
}

TEST_F(TrajectoryViewTest, IncompleteInputIsRejected) {
  TrajectoryView no_scene = View(true);
  no_scene.scene = nullptr;
  EXPECT_THROW(RenderTrajectoryView(no_scene), std::invalid_argument);
  TrajectoryView no_robot = View(true);
  no_robot.kinematics = nullptr;
  EXPECT_THROW(RenderTrajectoryView(no_robot), std::invalid_argument);
  TrajectoryView bad_start = View(true);
  bad_start.start.q_rad = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(RenderTrajectoryView(bad_start), std::invalid_argument);
  bad_start.start.q_rad = Eigen::VectorXd::Constant(model_.num_joints(), std::nan(""));
  EXPECT_THROW(RenderTrajectoryView(bad_start), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
