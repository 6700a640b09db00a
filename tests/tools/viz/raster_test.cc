#include "tools/viz/raster.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

const Rgb kRed{255, 0, 0};
const Rgb kBg{255, 255, 255};

int CountPixels(const Image& image, const Rgb& colour) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) count += image.At(x, y) == colour ? 1 : 0;
  }
  return count;
}

int CountChanged(const Image& image) {
  return image.width() * image.height() - CountPixels(image, kBg);
}

TEST(FillPolygonTest, AxisAlignedSquareCoversExactlyItsPixels) {
  Image image(20, 20, kBg);
  const std::vector<Eigen::Vector2d> square = {{2, 3}, {7, 3}, {7, 9}, {2, 9}};
  FillPolygon(&image, square, kRed);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 20; ++x) {
      const bool inside = x >= 2 && x < 7 && y >= 3 && y < 9;
      EXPECT_EQ(image.At(x, y) == kRed, inside) << "pixel " << x << ", " << y;
    }
  }
}

TEST(FillPolygonTest, TriangleAreaMatchesPixelCount) {
  Image image(100, 100, kBg);
  const std::vector<Eigen::Vector2d> triangle = {{10, 10}, {90, 10}, {10, 90}};
  FillPolygon(&image, triangle, kRed);
  const double area = 0.5 * 80 * 80;
  EXPECT_NEAR(CountPixels(image, kRed), area, 0.02 * area);
  EXPECT_EQ(image.At(20, 20), kRed);
  EXPECT_EQ(image.At(80, 80), kBg);  // Beyond the hypotenuse.
}

TEST(FillPolygonTest, ClipsAtTheImageBorderAndIgnoresDegenerateInput) {
  Image image(10, 10, kBg);
  const std::vector<Eigen::Vector2d> huge = {{-100, -100}, {100, -100}, {100, 100}, {-100, 100}};
  FillPolygon(&image, huge, kRed);
  EXPECT_EQ(CountPixels(image, kRed), 100);

  Image untouched(10, 10, kBg);
  const std::vector<Eigen::Vector2d> two = {{1, 1}, {8, 8}};
  FillPolygon(&untouched, two, kRed);
  const std::vector<Eigen::Vector2d> nan = {{1, 1}, {8, 1}, {std::nan(""), 8}};
  FillPolygon(&untouched, nan, kRed);
  EXPECT_EQ(CountChanged(untouched), 0);
}

TEST(FillPolygonTest, AlphaBlendsWithTheBackground) {
  Image image(4, 4, Rgb{0, 0, 0});
  const std::vector<Eigen::Vector2d> all = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  FillPolygon(&image, all, Rgb{200, 100, 50}, 0.5);
  EXPECT_EQ(image.At(1, 1), (Rgb{100, 50, 25}));
}

TEST(HatchPolygonTest, PaintsOnlyStripesInsideThePolygon) {
  Image image(40, 40, kBg);
  const std::vector<Eigen::Vector2d> square = {{10, 10}, {30, 10}, {30, 30}, {10, 30}};
  HatchPolygon(&image, square, kRed, 4, 1);
  const int painted = CountPixels(image, kRed);
  EXPECT_NEAR(painted, 400 / 4, 10);
  EXPECT_EQ(CountChanged(image), painted);
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (image.At(x, y) == kRed) {
        EXPECT_TRUE(x >= 10 && x < 30 && y >= 10 && y < 30);
        EXPECT_EQ((x + y) % 4, 0);
      }
    }
  }
}

TEST(DrawLineTest, HorizontalThickLineCoversItsBand) {
  Image image(30, 20, kBg);
  DrawLine(&image, {5, 10}, {25, 10}, kRed, 4.0);
  // Pixel centres within 1.5 px of y = 10 are fully covered: rows 8..11 between the ends.
  for (int x = 5; x < 25; ++x) {
    for (int y = 8; y <= 11; ++y) EXPECT_EQ(image.At(x, y), kRed) << x << ", " << y;
    EXPECT_EQ(image.At(x, 5), kBg);
    EXPECT_EQ(image.At(x, 15), kBg);
  }
  EXPECT_EQ(image.At(0, 10), kBg);
  EXPECT_EQ(image.At(29, 10), kBg);
}

TEST(DrawLineTest, DiagonalLineIsConnectedAndNarrow) {
  Image image(50, 50, kBg);
  DrawLine(&image, {5, 5}, {45, 45}, kRed, 1.0);
  for (int i = 5; i < 45; ++i) EXPECT_EQ(image.At(i, i), kRed) << i;
  EXPECT_EQ(image.At(10, 30), kBg);
  EXPECT_EQ(image.At(30, 10), kBg);
}

TEST(DrawPolylineTest, ClosedOutlineLeavesTheInsideUntouched) {
  Image image(40, 40, kBg);
  const std::vector<Eigen::Vector2d> square = {{10, 10}, {30, 10}, {30, 30}, {10, 30}};
  DrawPolyline(&image, square, /*closed=*/true, kRed, 2.0);
  EXPECT_EQ(image.At(20, 20), kBg);
  EXPECT_EQ(image.At(10, 20), kRed);  // Left edge (centre 10.5 is 0.5 px from x = 10).
  EXPECT_EQ(image.At(20, 29), kRed);  // Bottom edge, closing segment included.
  EXPECT_EQ(image.At(2, 2), kBg);
}

TEST(DrawPolylineTest, TranslucentSegmentsArePaintedOnceWhereTheyMeet) {
  Image image(40, 40, Rgb{0, 0, 0});
  const std::vector<Eigen::Vector2d> corner = {{5, 20}, {20, 20}, {20, 5}};
  DrawPolyline(&image, corner, false, Rgb{200, 200, 200}, 3.0, 0.5);
  EXPECT_EQ(image.At(19, 19), (Rgb{100, 100, 100}));  // At the joint.
  EXPECT_EQ(image.At(10, 19), (Rgb{100, 100, 100}));
}

TEST(CircleTest, FilledCircleCoversItsDiscOnly) {
  Image image(40, 40, kBg);
  FillCircle(&image, {20, 20}, 8.0, kRed);
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      const double d = std::hypot(x + 0.5 - 20, y + 0.5 - 20);
      if (d < 7.5) {
        EXPECT_EQ(image.At(x, y), kRed) << x << ", " << y;
      }
      if (d > 8.5) {
        EXPECT_EQ(image.At(x, y), kBg) << x << ", " << y;
      }
    }
  }
}

TEST(CircleTest, StrokedCircleIsARing) {
  Image image(40, 40, kBg);
  StrokeCircle(&image, {20, 20}, 10.0, kRed, 2.0);
  EXPECT_EQ(image.At(20, 20), kBg);
  EXPECT_EQ(image.At(29, 20), kRed);  // Centre 29.5 is 9.5 px away.
  EXPECT_EQ(image.At(20, 10), kRed);
  EXPECT_EQ(image.At(36, 20), kBg);
}

TEST(FillRectTest, ClipsToTheImage) {
  Image image(10, 10, kBg);
  FillRect(&image, -5, 8, 3, 20, kRed);
  EXPECT_EQ(CountPixels(image, kRed), 3 * 2);
  EXPECT_EQ(image.At(2, 9), kRed);
  EXPECT_EQ(image.At(3, 9), kBg);
}

}  // namespace
}  // namespace topay::viz
