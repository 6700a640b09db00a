#include "tools/viz/legend.h"

#include <gtest/gtest.h>

#include "tools/viz/color_map.h"

namespace topay::viz {
namespace {

const Eigen::AlignedBox2d kRoom(Eigen::Vector2d(0, 0), Eigen::Vector2d(20, 20));

bool IsPaper(const Image& image, int x0, int y0, int x1, int y1) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (image.At(x, y) != colors::kPaper) return false;
    }
  }
  return true;
}

TEST(LegendTest, ScaleBarLengthIsRoundAndFitsTheTarget) {
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 40.0), 100), 2.0);
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 40.0), 200), 5.0);
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 100.0), 100), 1.0);
  EXPECT_DOUBLE_EQ(LegendLayout::ScaleBarLength(ViewTransform(kRoom, 400.0), 100), 0.2);
}

TEST(LegendTest, ScaleBarIsDrawnAtItsLengthInPixels) {
  Image image(300, 40, colors::kPaper);
  Painter painter(&image);
  LegendLayout legend(&painter, 10, 10, 280, 12);
  const LegendBox bar = legend.ScaleBar(ViewTransform(kRoom, 40.0), 100);  // 2 m = 80 px.
  EXPECT_DOUBLE_EQ(bar.x0, 10.0);
  EXPECT_DOUBLE_EQ(bar.x1, 90.0);
  const int y = static_cast<int>(bar.y0);
  EXPECT_EQ(image.At(10, y), colors::kInk);
  EXPECT_EQ(image.At(89, y), colors::kInk);
  EXPECT_EQ(image.At(9, y), colors::kPaper);
  EXPECT_EQ(image.At(92, y), colors::kPaper);  // Gap before the "2 m" label...
  EXPECT_FALSE(IsPaper(image, 94, 10, 130, 30));  // ...which is drawn after it.
}

TEST(LegendTest, ColourBarRunsFromTheLowToTheHighColour) {
  Image image(400, 40, colors::kPaper);
  Painter painter(&image);
  LegendLayout legend(&painter, 5, 5, 390, 12);
  const LegendBox bar = legend.ColourBar("clearance", Viridis, "-0.3 m", "2.1 m");
  const int mid = static_cast<int>(0.5 * (bar.y0 + bar.y1));
  EXPECT_EQ(image.At(static_cast<int>(bar.x0), mid), Viridis(0.5 / (bar.x1 - bar.x0)));
  EXPECT_EQ(image.At(static_cast<int>(bar.x1) - 1, mid), Viridis(1.0 - 0.5 / (bar.x1 - bar.x0)));
  // Caption and low label left of the bar, high label right of it: all drawn (not paper).
  EXPECT_FALSE(IsPaper(image, 5, 5, static_cast<int>(bar.x0) - 2, 25));
  EXPECT_FALSE(IsPaper(image, static_cast<int>(bar.x1) + 2, 5, 400, 25));
}

TEST(LegendTest, MeasuringDrawsNothingAndMatchesDrawing) {
  Image image(200, 200, colors::kPaper);
  auto lay_out = [](LegendLayout* legend) {
    legend->Text("a fairly long title line");
    legend->Swatch(colors::kStart, colors::kInk, "start");
    legend->Swatch(colors::kGoal, colors::kInk, "goal");
    legend->LineKey(colors::kInk, 2.0, "path");
    legend->ScaleBar(ViewTransform(kRoom, 40.0));
  };
  LegendLayout measure(nullptr, 0, 0, 200, 12);
  lay_out(&measure);
  Painter painter(&image);
  LegendLayout draw(&painter, 0, 0, 200, 12);
  lay_out(&draw);
  EXPECT_EQ(measure.height(), draw.height());
  EXPECT_GT(draw.height(), LineHeight(12) + 6.0);  // Wrapped to a second row.
  EXPECT_FALSE(IsPaper(image, 0, 0, 200, static_cast<int>(draw.height())));
  // Nothing below the measured height.
  EXPECT_TRUE(IsPaper(image, 0, static_cast<int>(std::ceil(draw.height())), 200, 200));
}

}  // namespace
}  // namespace topay::viz
