#include "tools/viz/trajectory_drawing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/io/robot_loader.h"
#include "tests/core/validate/rest_to_rest_motion.h"

namespace topay::viz {
namespace {

class TrajectoryDrawingTest : public ::testing::Test {
 protected:
  TrajectoryDrawingTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        trajectory_(model_.num_joints(), 1, {}) {
    // Straight along +x from (-3, 0) to (3, 0) in 8 s, the arm still.
    topay::testing::RestToRest motion;
    motion.p0_W = Eigen::Vector2d(-3.0, 0.0);
    motion.s_f_m = 6.0;
    motion.q0_rad = Eigen::VectorXd::Zero(model_.num_joints());
    motion.q_f_rad = motion.q0_rad;
    motion.duration_s = 8.0;
    topay::testing::UpdateRestToRest(motion, &trajectory_);
  }

  // 10 x 10 m centred on the origin at 20 px/m.
  static WorldCanvas MakeCanvas() {
    const ViewTransform view(Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5)),
                             20.0);
    return WorldCanvas(Image(view.width_px(), view.height_px()), view);
  }

  // True if a pixel of exactly `colour` lies within `radius_px` of p_W.
  static bool ColourNear(const WorldCanvas& canvas, const Eigen::Vector2d& p_W, const Rgb& colour,
                         int radius_px = 2) {
    const Eigen::Vector2d p = canvas.view().ToPixel(p_W);
    for (int dy = -radius_px; dy <= radius_px; ++dy) {
      for (int dx = -radius_px; dx <= radius_px; ++dx) {
        const int x = static_cast<int>(p.x()) + dx, y = static_cast<int>(p.y()) + dy;
        if (canvas.image().Contains(x, y) && canvas.image().At(x, y) == colour) return true;
      }
    }
    return false;
  }

  double XAt(double t_s) const { return -3.0 + 6.0 * topay::testing::Ramp(t_s / 8.0); }

  RobotModel model_;
  Kinematics kinematics_;
  ArcYawTrajectory trajectory_;
};

TEST(FootprintTimesTest, RegularTimesStrictlyInsideAndNotOnTheEnd) {
  EXPECT_EQ(FootprintTimes(8.0, 2.0), (std::vector<double>{2.0, 4.0, 6.0}));
  EXPECT_EQ(FootprintTimes(8.6, 2.0), (std::vector<double>{2.0, 4.0, 6.0, 8.0}));
  EXPECT_EQ(FootprintTimes(8.4, 2.0), (std::vector<double>{2.0, 4.0, 6.0}));  // 8 is too close
  EXPECT_TRUE(FootprintTimes(0.3, 1.0).empty());
  EXPECT_TRUE(FootprintTimes(0.0, 1.0).empty());
  EXPECT_THROW(FootprintTimes(8.0, 0.0), std::invalid_argument);
  EXPECT_THROW(FootprintTimes(8.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(FootprintTimes(-1.0, 1.0), std::invalid_argument);
}

TEST_F(TrajectoryDrawingTest, BasePathSamplesRunFromStartToTheExactEnd) {
  const std::vector<Eigen::Vector2d> path = SampleBasePath(trajectory_, 0.01);
  ASSERT_EQ(path.size(), 801u);
  EXPECT_TRUE(path.front().isApprox(Eigen::Vector2d(-3.0, 0.0), 1e-12));
  // x comes from Simpson's rule (12 panels of h = 8/12 s): error <= t / 2880 h^4 max|f^(4)|,
  // f = s' = (6 / 8) RampRate(t / 8), whose fourth derivative is the constant 720 (6 / 8) / 8^4.
  const double h = 8.0 / 12.0;
  const double f4 = 720.0 * (6.0 / 8.0) / std::pow(8.0, 4);
  auto bound = [&](double t_s) { return t_s / 2880.0 * std::pow(h, 4) * f4 * (1.0 + 1e-9); };
  EXPECT_NEAR(path.back().x(), 3.0, bound(8.0));
  EXPECT_NEAR(path.back().y(), 0.0, 1e-12);
  EXPECT_NEAR(path[400].x(), XAt(4.0), bound(4.0));
  EXPECT_THROW(SampleBasePath(trajectory_, 0.0), std::invalid_argument);
}

TEST_F(TrajectoryDrawingTest, DrawsThePathAndFootprintsColouredByTime) {
  WorldCanvas canvas = MakeCanvas();
  TrajectoryDrawingStyle style;
  style.footprint_interval_s = 2.0;
  DrawTrajectory(&canvas, trajectory_, kinematics_, style);
  // Between footprints (t = 2, 4, 6 s at x = -2.38, 0, 2.38 m) the path shows in its colour.
  EXPECT_TRUE(ColourNear(canvas, {-1.2, 0.0}, style.path_colour, 0));
  EXPECT_TRUE(ColourNear(canvas, {1.2, 0.0}, style.path_colour, 0));
  // Off the path and away from footprints: untouched.
  EXPECT_EQ(canvas.image().At(canvas.view().ToPixel({-1.2, 1.5}).x(),
                              canvas.view().ToPixel({-1.2, 1.5}).y()),
            colors::kWhite);
  // Each footprint's chassis outline (front edge, 0.3425 m ahead) in its time's colour.
  for (double t_s : {2.0, 4.0, 6.0}) {
    const Rgb colour = FootprintColour(style, t_s, 8.0);
    EXPECT_TRUE(ColourNear(canvas, {XAt(t_s) + 0.3425, -0.2}, colour)) << t_s;
    EXPECT_FALSE(ColourNear(canvas, {XAt(t_s) + 0.3425, -1.0}, colour, 4)) << t_s;
  }
  EXPECT_NE(FootprintColour(style, 2.0, 8.0), FootprintColour(style, 6.0, 8.0));
  // t = 0 and the end are left to the caller: no footprint in the start colour there.
  EXPECT_FALSE(ColourNear(canvas, {-3.0 + 0.3425, -0.2}, style.early_colour));
}

TEST_F(TrajectoryDrawingTest, RejectsAnotherRobotOrAnUnsolvedTrajectory) {
  WorldCanvas canvas = MakeCanvas();
  ArcYawTrajectory two_joints(2, 1, {});
  topay::testing::RestToRest motion;
  motion.s_f_m = 1.0;
  motion.q0_rad = motion.q_f_rad = Eigen::Vector2d::Zero();
  topay::testing::UpdateRestToRest(motion, &two_joints);
  EXPECT_THROW(DrawTrajectory(&canvas, two_joints, kinematics_), std::invalid_argument);
  ArcYawTrajectory unsolved(model_.num_joints(), 1, {});
  EXPECT_THROW(DrawTrajectory(&canvas, unsolved, kinematics_), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
