#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tools/viz/color.h"
#include "tools/viz/image.h"
#include "tools/viz/painter.h"

namespace topay::viz {

/// One curve y(x) of a chart: x and y of equal length (non-finite points leave a gap).
struct ChartSeries {
  std::vector<double> x;
  std::vector<double> y;
  Rgb colour = colors::kInk;
  std::string label;  ///< Legend entry; empty: none.
  double width_px = 2.0;
  /// Draw each point as a dot of this radius (px) instead of joining them (a scatter plot).
  double marker_radius_px = 0.0;
};

/// A horizontal reference line y = value across the plot (a limit), dashed.
struct ChartLimitLine {
  double y = 0.0;
  Rgb colour{200, 30, 30};
  std::string label;  ///< Written at the line's right end inside the plot; empty: none.
  double width_px = 1.5;
  DashPattern dash;
};

/// What one chart shows. Unset ranges are fitted: x to the series' x extent, y to the series'
/// y values and every limit line, padded (ChartStyle::y_padding).
struct LineChart {
  std::string title;    ///< Above the plot, left.
  std::string y_label;  ///< Above the plot, after the title, e.g. "v (m/s)".
  std::string x_label;  ///< Under the x tick labels, e.g. "t (s)"; empty: no line for it.
  std::vector<ChartSeries> series;
  std::vector<ChartLimitLine> limit_lines;
  std::optional<std::pair<double, double>> x_range;
  std::optional<std::pair<double, double>> y_range;
  bool show_legend = false;  ///< Series labels, right-aligned in the title row.
  /// Named x positions (e.g. categories) drawn instead of the numeric x ticks; empty: numbers.
  std::vector<std::pair<double, std::string>> x_tick_labels;
  /// Fixed y tick step (e.g. 20 for percentages); unset: NiceTickStep.
  std::optional<double> y_step;
};

struct ChartStyle {
  double font_px = 12.0;    ///< Text height (Painter::Text size).
  int target_x_ticks = 10;  ///< About this many intervals (NiceTickStep).
  int target_y_ticks = 4;
  double y_padding = 0.06;  ///< Fraction of the fitted y span added at each end.
  Rgb frame{30, 30, 30};
  Rgb grid{225, 225, 225};
  Rgb background = colors::kWhite;
  /// Distance (px) from the area's left edge to the plot; 0: just wide enough for the y tick
  /// labels. Stacked charts set the largest of theirs so their plots line up.
  int plot_left_inset_px = 0;
};

/// A pixel rectangle: x0 <= x < x1, y0 <= y < y1.
struct PixelRect {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

/// Where a drawn chart's plot lies and what it shows, for callers that add to it and for
/// tests.
struct ChartLayout {
  PixelRect plot;  ///< The data area inside the frame.
  double x_min = 0.0, x_max = 1.0, y_min = 0.0, y_max = 1.0;
  std::vector<double> x_ticks, y_ticks;
  double x_step = 1.0, y_step = 1.0;

  /// Pixel position of data point (x, y): x_min maps to plot.x0, x_max to plot.x1, y_max to
  /// plot.y0 and y_min to plot.y1 (linear in between).
  Eigen::Vector2d ToPixel(double x, double y) const;
};

/// Lays out the chart in `area` without drawing: a title row (title, y label, legend), y tick
/// labels on the left, x tick labels (and x_label) below. Throws std::invalid_argument for series
/// of unequal x and y sizes, an empty or non-finite range (nothing finite to fit), a font_px
/// outside [4, 64], or an area too small for a plot of at least 10 x 10 pixels.
ChartLayout LayOutLineChart(const PixelRect& area, const LineChart& chart,
                            const ChartStyle& style = {});

/// Draws the chart into `area` (as laid out by LayOutLineChart): background, grid at the
/// ticks, tick labels, dashed limit lines with their labels, the series clipped to the plot in
/// order (later series on top), the frame, the title and y label, the x label and the legend.
ChartLayout DrawLineChart(Painter* painter, const PixelRect& area, const LineChart& chart,
                          const ChartStyle& style = {});
/// The same on a fresh painter of the image.
ChartLayout DrawLineChart(Image* image, const PixelRect& area, const LineChart& chart,
                          const ChartStyle& style = {});

}  // namespace topay::viz
