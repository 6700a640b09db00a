#include "tools/viz/legend.h"

#include <gtest/gtest.h>

#include "tools/viz/bitmap_font.h"

namespace topay::viz {
namespace {

const Eigen::AlignedBox2d kRoom(Eigen::Vector2d(0, 0), Eigen::Vector2d(20, 20));

TEST(LegendTest, ScaleBarLengthIsRoundAndFitsTheTarget) {
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 40.0), 100), 2.0);
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 40.0), 200), 5.0);
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 100.0), 100), 1.0);
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 400.0), 100), 0.2);
}

TEST(LegendTest, ScaleBarIsDrawnAtItsLengthInPixels) {
  Image image(300, 40, colors::kPaper);
  LegendLayout legend(&image, 10, 10, 280, 1);
  legend.ScaleBar(ViewTransform(kRoom, 40.0), 100);  // 2 m = 80 px.
  const int bar_y = 10 + BitmapFont::TextHeight(1) / 2;
  EXPECT_EQ(image.At(10, bar_y), colors::kInk);
  EXPECT_EQ(image.At(89, bar_y), colors::kInk);
  EXPECT_EQ(image.At(92, bar_y), colors::kPaper);  // Gap before the "2 m" label.
  EXPECT_EQ(image.At(9, bar_y), colors::kPaper);
}

TEST(LegendTest, MeasuringDrawsNothingAndMatchesDrawing) {
  Image image(200, 200, colors::kPaper);
  const Image blank = image;
  auto lay_out = [](LegendLayout* legend) {
    legend->Text("a fairly long title line");
    legend->Swatch(colors::kStart, colors::kInk, "start");
    legend->Swatch(colors::kGoal, colors::kInk, "goal");
    legend->ScaleBar(ViewTransform(kRoom, 40.0));
  };
  LegendLayout measure(nullptr, 0, 0, 200, 1);
  lay_out(&measure);
  LegendLayout draw(&image, 0, 0, 200, 1);
  lay_out(&draw);
  EXPECT_EQ(measure.height(), draw.height());
  EXPECT_GT(draw.height(), (BitmapFont::kLineHeight + 4));  // Wrapped to a second row.
  EXPECT_NE(image.bytes(), blank.bytes());
  // Nothing below the measured height.
  for (int y = draw.height(); y < 200; ++y) {
    for (int x = 0; x < 200; ++x) ASSERT_EQ(image.At(x, y), colors::kPaper) << x << ", " << y;
  }
}

}  // namespace
}  // namespace topay::viz
