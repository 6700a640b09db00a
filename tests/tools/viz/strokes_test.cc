#include "tools/viz/strokes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "tools/viz/raster.h"

namespace topay::viz {
namespace {

constexpr Rgb kRed{220, 0, 0};

int CountColour(const Image& image, const Rgb& colour) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) count += image.At(x, y) == colour ? 1 : 0;
  }
  return count;
}

TEST(StrokesTest, LongPolylinePaintsLikeOnePolylineAwayFromRunJoints) {
  // A sine wave of 400 points: DrawLongPolyline in runs of 16 against DrawPolyline at once.
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 400; ++i) {
    points.emplace_back(5.0 + 0.5 * i, 50.0 + 30.0 * std::sin(0.03 * i));
  }
  Image chunked(220, 100), whole(220, 100);
  DrawLongPolyline(&chunked, points, kRed, 2.0);
  DrawPolyline(&whole, points, false, kRed, 2.0);
  // Runs of 16 points share their end points: the joints are points 15, 30, 45, ...
  auto near_joint = [&](int x, int y) {
    for (std::size_t j = 15; j < points.size(); j += 15) {
      if ((Eigen::Vector2d(x + 0.5, y + 0.5) - points[j]).norm() <= 1.0 + 1.0) return true;
    }
    return false;
  };
  int differing = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 220; ++x) {
      const Rgb a = chunked.At(x, y), b = whole.At(x, y);
      // Fully covered pixels agree exactly; only rim pixels within reach of two runs (around
      // a joint: half width + 1 px) may be painted twice.
      if (b == kRed) {
        EXPECT_EQ(a, kRed) << x << ", " << y;
      }
      if (a != b) {
        ++differing;
        EXPECT_TRUE(near_joint(x, y)) << x << ", " << y;
      }
    }
  }
  EXPECT_GT(CountColour(whole, kRed), 300);
  EXPECT_GT(differing, 0);  // the joints' rims do show (so the runs really were split)
}

TEST(StrokesTest, NonFinitePointsSplitTheLine) {
  const double nan = std::nan("");
  const std::vector<Eigen::Vector2d> points = {{5, 10}, {45, 10}, {nan, nan}, {55, 10}, {95, 10}};
  Image image(100, 20);
  DrawLongPolyline(&image, points, kRed, 3.0);
  EXPECT_EQ(image.At(20, 10), kRed);
  EXPECT_EQ(image.At(75, 10), kRed);
  EXPECT_EQ(image.At(50, 10), colors::kWhite);  // no segment across the gap
}

TEST(StrokesTest, LongPolylineRejectsRunsShorterThanTwoPoints) {
  Image image(10, 10);
  const std::vector<Eigen::Vector2d> points = {{1, 1}, {8, 8}};
  EXPECT_THROW(DrawLongPolyline(&image, points, kRed, 1.0, 1.0, 1), std::invalid_argument);
}

TEST(StrokesTest, DashedLinePaintsDashesAndLeavesGaps) {
  Image image(100, 11);
  DrawDashedLine(&image, {0.0, 5.5}, {100.0, 5.5}, kRed, 3.0, DashPattern{8.0, 5.0});
  // Dashes cover [0, 8), [13, 21), ... along x (with anti-aliased round caps).
  for (int period = 0; period < 7; ++period) {
    const int start = 13 * period;
    EXPECT_EQ(image.At(start + 4, 5), kRed) << "dash " << period;
    EXPECT_EQ(image.At(start + 10, 5), colors::kWhite) << "gap " << period;
  }
  EXPECT_EQ(image.At(50, 0), colors::kWhite);  // 3 px wide: row 0 untouched
  Image untouched(20, 20);
  DrawDashedLine(&untouched, {0, 0}, {std::nan(""), 5}, kRed, 2.0);
  DrawDashedLine(&untouched, {0, 0}, {10, 10}, kRed, 2.0, DashPattern{0.0, 3.0});
  EXPECT_EQ(CountColour(untouched, colors::kWhite), 400);
}

}  // namespace
}  // namespace topay::viz
