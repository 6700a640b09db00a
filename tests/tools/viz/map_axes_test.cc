#include "tools/viz/map_axes.h"

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

TEST(MapAxesTest, TicksAreRoundMetresInsideTheRegion) {
  // 20.5 m over 820 px, about one tick per 60 px: 13 intervals -> every 2 m.
  const ViewTransform view(
      Eigen::AlignedBox2d(Eigen::Vector2d(-10.25, -5.25), Eigen::Vector2d(10.25, 5.25)), 40.0);
  const MapTicks ticks = MapAxisTicks(view);
  EXPECT_DOUBLE_EQ(ticks.step_m, 2.0);
  ASSERT_EQ(ticks.x_m.size(), 11u);
  EXPECT_DOUBLE_EQ(ticks.x_m.front(), -10.0);
  EXPECT_DOUBLE_EQ(ticks.x_m.back(), 10.0);
  ASSERT_EQ(ticks.y_m.size(), 5u);
  EXPECT_DOUBLE_EQ(ticks.y_m.front(), -4.0);
  // A coarser spacing gives a coarser step.
  MapAxesStyle coarse;
  coarse.tick_spacing_px = 150.0;  // 5 intervals -> every 5 m.
  EXPECT_DOUBLE_EQ(MapAxisTicks(view, coarse).step_m, 5.0);
}

TEST(MapAxesTest, DrawsFrameTicksAndLabelsOutsideTheMap) {
  const MapAxesStyle style;
  const double left = std::ceil(MapAxesLeftPx(style));
  const double bottom = std::ceil(MapAxesBottomPx(style));
  const ViewTransform view(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(5, 5)),
                           40.0, Eigen::Vector2d(left, 10));
  Image image(static_cast<int>(left) + 200 + 10, 10 + 200 + static_cast<int>(bottom));
  Painter painter(&image);
  DrawMapAxes(&painter, view, style);
  // The inside of the map is untouched.
  for (int y = 15; y < 205; ++y) {
    for (int x = static_cast<int>(left) + 5; x < static_cast<int>(left) + 195; ++x) {
      ASSERT_EQ(image.At(x, y), colors::kWhite) << x << ", " << y;
    }
  }
  // 200 px, a tick about every 60 px: every 2 m. The frame just outside the map's left edge;
  // a tick under x = 2 m, its label "2" below it.
  EXPECT_DOUBLE_EQ(MapAxisTicks(view, style).step_m, 2.0);
  EXPECT_NE(image.At(static_cast<int>(left) - 1, 100), colors::kWhite);
  const int u = static_cast<int>(view.ToPixel({2.0, 0.0}).x());
  EXPECT_NE(image.At(u, 213), colors::kWhite);
  int label_ink = 0;
  for (int y = 217; y < 232; ++y) {
    for (int x = u - 6; x < u + 6; ++x) label_ink += image.At(x, y) != colors::kWhite;
  }
  EXPECT_GT(label_ink, 5);
}

}  // namespace
}  // namespace topay::viz
