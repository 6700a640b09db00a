#include "tools/viz/painter.h"

#include <vector>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

const Rgb kRed{255, 0, 0};

int CountNot(const Image& image, const Rgb& colour, int x0, int y0, int x1, int y1) {
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) count += image.At(x, y) != colour;
  }
  return count;
}

TEST(PainterTest, PolygonFillsItsInsideOnly) {
  Image image(40, 40);
  Painter painter(&image);
  const std::vector<Eigen::Vector2d> square = {{10, 10}, {30, 10}, {30, 20}, {10, 20}};
  painter.FillPolygon(square, kRed);
  EXPECT_EQ(image.At(10, 10), kRed);
  EXPECT_EQ(image.At(29, 19), kRed);
  EXPECT_EQ(image.At(30, 15), colors::kWhite);
  EXPECT_EQ(image.At(20, 9), colors::kWhite);
  EXPECT_EQ(image.At(20, 20), colors::kWhite);
}

TEST(PainterTest, TranslucentFillBlendsAndEdgesAreAntiAliased) {
  Image image(20, 20, Rgb{0, 0, 0});
  Painter painter(&image);
  painter.FillRect(0, 0, 10, 20, colors::kWhite, 0.5);
  const Rgb half = image.At(5, 5);
  EXPECT_NEAR(half.r, 128, 1);
  EXPECT_EQ(image.At(15, 5), (Rgb{0, 0, 0}));
  // A rectangle edge at x = 12.5 half covers pixel 12.
  painter.FillRect(12.5, 0, 18, 20, colors::kWhite);
  EXPECT_NEAR(image.At(12, 5).r, 128, 2);
  EXPECT_EQ(image.At(13, 5), colors::kWhite);
}

TEST(PainterTest, DashedLineHasGaps) {
  Image image(100, 10);
  Painter painter(&image);
  painter.DrawDashedLine({0, 5}, {100, 5}, kRed, 2.0, {8.0, 5.0});
  EXPECT_EQ(image.At(4, 5), kRed);          // First dash: 0..8.
  EXPECT_EQ(image.At(10, 5), colors::kWhite);  // Gap: 8..13.
  EXPECT_EQ(image.At(17, 5), kRed);         // Second dash: 13..21.
}

TEST(PainterTest, HatchStripesStayInsideThePolygon) {
  Image image(60, 60);
  Painter painter(&image);
  const std::vector<Eigen::Vector2d> square = {{10, 10}, {40, 10}, {40, 40}, {10, 40}};
  painter.HatchPolygon(square, kRed, 5.0, 1.0);
  EXPECT_GT(CountNot(image, colors::kWhite, 10, 10, 40, 40), 100);
  // Stripes, not a fill: a quarter of the inside or more stays white.
  EXPECT_LT(CountNot(image, colors::kWhite, 10, 10, 40, 40), 30 * 30 * 3 / 4);
  EXPECT_EQ(CountNot(image, colors::kWhite, 0, 0, 60, 9), 0);
  EXPECT_EQ(CountNot(image, colors::kWhite, 41, 0, 60, 60), 0);
}

TEST(PainterTest, TextIsDrawnInItsBoxAndMeasured) {
  Image image(200, 40);
  Painter painter(&image);
  painter.Text(10, 5, "x (m) 10", colors::kInk, 14.0);
  const double width = TextWidth("x (m) 10", 14.0);
  EXPECT_GT(width, 30.0);
  EXPECT_LT(width, 90.0);
  EXPECT_GT(TextWidth("x (m) 10 20", 14.0), width);
  EXPECT_DOUBLE_EQ(TextWidth("", 14.0), 0.0);
  // Ink inside the text's box, none left of it, right of it or below its line.
  const int right = static_cast<int>(10 + width) + 2;
  const int bottom = static_cast<int>(5 + LineHeight(14.0)) + 1;
  EXPECT_GT(CountNot(image, colors::kWhite, 10, 5, right, bottom), 20);
  EXPECT_EQ(CountNot(image, colors::kWhite, 0, 0, 9, 40), 0);
  EXPECT_EQ(CountNot(image, colors::kWhite, right, 0, 200, 40), 0);
  EXPECT_EQ(CountNot(image, colors::kWhite, 0, bottom, 200, 40), 0);
}

TEST(PainterTest, RightAlignedTextEndsAtX) {
  Image image(200, 30);
  Painter painter(&image);
  painter.Text(150, 5, "12.5", colors::kInk, 12.0, TextAlign::kRight);
  EXPECT_EQ(CountNot(image, colors::kWhite, 152, 0, 200, 30), 0);
  EXPECT_GT(CountNot(image, colors::kWhite, 150 - static_cast<int>(TextWidth("12.5", 12.0)), 0,
                     150, 30),
            10);
}

TEST(PainterTest, ClipKeepsDrawingInsideUntilPopped) {
  Image image(40, 40);
  Painter painter(&image);
  painter.PushClip(10, 10, 20, 20);
  painter.FillRect(0, 0, 40, 40, kRed);
  painter.PopClip();
  EXPECT_EQ(image.At(15, 15), kRed);
  EXPECT_EQ(image.At(25, 15), colors::kWhite);
  painter.FillRect(30, 30, 40, 40, kRed);
  EXPECT_EQ(image.At(35, 35), kRed);
}

TEST(PainterTest, PolylineSplitsAtNonFinitePoints) {
  Image image(60, 20);
  Painter painter(&image);
  const std::vector<Eigen::Vector2d> points = {
      {0, 10}, {20, 10}, Eigen::Vector2d::Constant(std::nan("")), {40, 10}, {60, 10}};
  painter.DrawPolyline(points, /*closed=*/false, kRed, 2.0);
  EXPECT_EQ(image.At(10, 10), kRed);
  EXPECT_EQ(image.At(30, 10), colors::kWhite);  // Not bridged.
  EXPECT_EQ(image.At(50, 10), kRed);
}

}  // namespace
}  // namespace topay::viz
