// path.png's region and scale: the scene's bounds (else the map's) and everything drawn.

#include "tools/report/path_plot_view.h"

#include <gtest/gtest.h>

#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

TEST(PathPlotView, RegionCoversTheRoomAndTheRun) {
  RunLog log;
  EXPECT_EQ(PathPlotRegion(log, nullptr, {}).min(), Eigen::Vector2d(-1, -1));  // nothing: 2 x 2 m
  log.robot_states.resize(1);
  log.robot_states[0].state.x_m = 7.0;
  log.robot_states[0].state.y_m = -3.0;
  log.map = FinalMap{test::MapGeometry(), {}};  // x, y -1..3
  Eigen::AlignedBox2d region = PathPlotRegion(log, nullptr, {});
  EXPECT_EQ(region.min(), Eigen::Vector2d(-1, -3));
  EXPECT_EQ(region.max(), Eigen::Vector2d(7, 3));
  Scene scene;  // the scene's bounds replace the map's
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
  region = PathPlotRegion(log, &scene, {});
  EXPECT_EQ(region.min(), Eigen::Vector2d(-5, -5));
  EXPECT_EQ(region.max(), Eigen::Vector2d(7, 5));
}

TEST(PathPlotView, ScaleFitsTheLongerSideUnlessGiven) {
  RunLog log;
  log.map = FinalMap{test::MapGeometry(), {}};  // 4 x 4 m, + 2 x 0.5 m margin: 5 m
  PathPlotOptions options;
  viz::ViewTransform view = PathPlotView(log, nullptr, options);
  EXPECT_DOUBLE_EQ(view.px_per_m(), 200.0);  // 1000 / 5 = 200 (the upper clamp)
  options.target_map_px = 500;
  view = PathPlotView(log, nullptr, options);
  EXPECT_DOUBLE_EQ(view.px_per_m(), 100.0);
  EXPECT_EQ(view.width_px(), 500);
  EXPECT_EQ(PathPlotWidth(view, options), static_cast<int>(view.offset_px().x()) + 500 + 16);
  options.px_per_m = 30.0;
  EXPECT_DOUBLE_EQ(PathPlotView(log, nullptr, options).px_per_m(), 30.0);
}

}  // namespace
}  // namespace topay::report
