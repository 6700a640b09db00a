#include "tools/viz/line_chart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace topay::viz {
namespace {

constexpr Rgb kBlue{0, 90, 181};
constexpr Rgb kRed{200, 30, 30};

Eigen::Vector2i Pixel(const ChartLayout& layout, double x, double y) {
  const Eigen::Vector2d p = layout.ToPixel(x, y);
  return {static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y()))};
}

// A constant series y = 0.5 over x in [0, 10] and dashed limits at +-1.
LineChart ConstantChart() {
  LineChart chart;
  chart.title = "test";
  chart.y_label = "(m/s)";
  chart.x_label = "t (s)";
  ChartSeries series;
  for (int i = 0; i <= 100; ++i) {
    series.x.push_back(0.1 * i);
    series.y.push_back(0.5);
  }
  series.colour = kBlue;
  series.width_px = 3.0;
  chart.series.push_back(series);
  ChartLimitLine upper;
  upper.y = 1.0;
  upper.colour = kRed;
  upper.width_px = 2.0;
  ChartLimitLine lower = upper;
  lower.y = -1.0;
  chart.limit_lines = {upper, lower};
  return chart;
}

TEST(LineChartTest, LayoutFitsTheDataAndTheLimitsAndMapsCornersToThePlot) {
  const PixelRect area{10, 20, 610, 220};
  const ChartLayout layout = LayOutLineChart(area, ConstantChart());
  EXPECT_DOUBLE_EQ(layout.x_min, 0.0);
  EXPECT_DOUBLE_EQ(layout.x_max, 10.0);
  // y: [-1, 1] (the limits include the data) padded by 6 % of the span at each end.
  EXPECT_NEAR(layout.y_min, -1.12, 1e-12);
  EXPECT_NEAR(layout.y_max, 1.12, 1e-12);
  EXPECT_GT(layout.plot.x0, area.x0);
  EXPECT_LT(layout.plot.x1, area.x1);
  EXPECT_GT(layout.plot.y0, area.y0);
  EXPECT_LT(layout.plot.y1, area.y1);
  EXPECT_TRUE(
      layout.ToPixel(0.0, layout.y_max).isApprox(Eigen::Vector2d(layout.plot.x0, layout.plot.y0)));
  EXPECT_TRUE(
      layout.ToPixel(10.0, layout.y_min).isApprox(Eigen::Vector2d(layout.plot.x1, layout.plot.y1)));
  EXPECT_EQ(layout.x_ticks, (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  // y span 2.24 over about 4 intervals: step 1 (the smallest round step >= 0.56).
  EXPECT_EQ(layout.y_ticks, (std::vector<double>{-1.0, 0.0, 1.0}));
  // A fixed left inset puts the plot there.
  ChartStyle style;
  style.plot_left_inset_px = 77;
  EXPECT_EQ(LayOutLineChart(area, ConstantChart(), style).plot.x0, area.x0 + 77);
}

TEST(LineChartTest, SeriesIsDrawnWhereItsValuesMapAndNowhereElse) {
  Image image(640, 240, colors::kPaper);
  const PixelRect area{10, 20, 610, 220};
  const ChartLayout layout = DrawLineChart(&image, area, ConstantChart());
  // Along the whole x range, the series' row is blue.
  for (double x = 0.5; x < 10.0; x += 0.5) {
    const Eigen::Vector2i p = Pixel(layout, x, 0.5);
    EXPECT_EQ(image.At(p.x(), p.y()), kBlue) << "x = " << x;
    // 5 px above and below (beyond the 3 px width) it is not.
    EXPECT_NE(image.At(p.x(), p.y() - 5), kBlue) << "x = " << x;
    EXPECT_NE(image.At(p.x(), p.y() + 5), kBlue) << "x = " << x;
  }
  // The value -0.5 has no series.
  const Eigen::Vector2i below = Pixel(layout, 3.3, -0.5);
  EXPECT_NE(image.At(below.x(), below.y()), kBlue);
  // Nothing is drawn outside the area.
  EXPECT_EQ(image.At(5, 100), colors::kPaper);
  EXPECT_EQ(image.At(620, 100), colors::kPaper);
  EXPECT_EQ(image.At(300, 10), colors::kPaper);
  EXPECT_EQ(image.At(300, 230), colors::kPaper);
}

TEST(LineChartTest, LimitLinesAreDashedAtTheirValues) {
  Image image(640, 240);
  const ChartLayout layout = DrawLineChart(&image, {10, 20, 610, 220}, ConstantChart());
  for (double limit : {1.0, -1.0}) {
    const int row = Pixel(layout, 0.0, limit).y();
    int red = 0, other = 0, runs = 0;
    bool in_dash = false;
    for (int x = layout.plot.x0 + 3; x < layout.plot.x1 - 3; ++x) {
      const bool is_red = image.At(x, row) == kRed;
      red += is_red ? 1 : 0;
      other += is_red ? 0 : 1;
      runs += (is_red && !in_dash) ? 1 : 0;
      in_dash = is_red;
    }
    // Dashes of 8 px every 13 px: many separate red runs, with gaps between them.
    EXPECT_GT(runs, layout.plot.width() / 13 - 3) << limit;
    EXPECT_GT(red, other) << limit;
    EXPECT_GT(other, 0) << limit;
  }
  // Half-way between the limits and the series there is no red.
  const Eigen::Vector2i between = Pixel(layout, 5.0, 0.75);
  EXPECT_NE(image.At(between.x(), between.y()), kRed);
}

TEST(LineChartTest, SeriesOutsideAFixedRangeIsClippedToThePlot) {
  LineChart chart = ConstantChart();
  chart.limit_lines.clear();
  chart.series[0].y.assign(chart.series[0].y.size(), 5.0);  // far above the range
  chart.y_range = std::make_pair(-1.0, 1.0);
  chart.title.clear();
  chart.y_label.clear();
  Image image(640, 240);
  const ChartLayout layout = DrawLineChart(&image, {10, 20, 610, 220}, chart);
  int blue = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) blue += image.At(x, y) == kBlue ? 1 : 0;
  }
  EXPECT_EQ(blue, 0);
  // A series crossing the range is drawn inside it up to the frame.
  chart.series[0].y = chart.series[0].x;  // y = x: leaves the range at x = 1
  Image crossing(640, 240);
  DrawLineChart(&crossing, {10, 20, 610, 220}, chart);
  const Eigen::Vector2i inside = Pixel(layout, 0.5, 0.5);
  EXPECT_EQ(crossing.At(inside.x(), inside.y()), kBlue);
  for (int x = 0; x < crossing.width(); ++x) {
    for (int y = 0; y < layout.plot.y0 - 2; ++y) {
      EXPECT_NE(crossing.At(x, y), kBlue) << x << ", " << y;
    }
  }
}

TEST(LineChartTest, GapsInTheDataAreNotBridged) {
  LineChart chart = ConstantChart();
  chart.series[0].y[50] = std::nan("");  // x = 5
  Image image(640, 240);
  const ChartLayout layout = DrawLineChart(&image, {10, 20, 610, 220}, chart);
  const Eigen::Vector2i gap = Pixel(layout, 5.0, 0.5);
  EXPECT_NE(image.At(gap.x(), gap.y()), kBlue);
  const Eigen::Vector2i drawn = Pixel(layout, 4.0, 0.5);
  EXPECT_EQ(image.At(drawn.x(), drawn.y()), kBlue);
}

TEST(LineChartTest, BadChartsAreRejectedByName) {
  LineChart chart = ConstantChart();
  chart.series[0].y.pop_back();
  try {
    LayOutLineChart({0, 0, 600, 200}, chart);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("test"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("101 x values and 100 y values"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(LayOutLineChart({0, 0, 30, 30}, ConstantChart()), std::invalid_argument);
  LineChart empty;
  EXPECT_THROW(LayOutLineChart({0, 0, 600, 200}, empty), std::invalid_argument);
  LineChart reversed = ConstantChart();
  reversed.x_range = std::make_pair(2.0, 1.0);
  EXPECT_THROW(LayOutLineChart({0, 0, 600, 200}, reversed), std::invalid_argument);
  ChartStyle style;
  style.font_px = 0.0;
  EXPECT_THROW(LayOutLineChart({0, 0, 600, 200}, ConstantChart(), style), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
