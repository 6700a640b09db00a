#include "tools/viz/line_chart.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "tools/viz/bitmap_font.h"
#include "tools/viz/chart_ticks.h"
#include "tools/viz/raster.h"

namespace topay::viz {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Extent {
  double lo = kInf;
  double hi = -kInf;
  void Add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return lo > hi; }
};

void CheckSeries(const LineChart& chart) {
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const ChartSeries& s = chart.series[i];
    if (s.x.size() != s.y.size()) {
      throw std::invalid_argument("line chart '" + chart.title + "': series " + std::to_string(i) +
                                  " ('" + s.label + "') has " + std::to_string(s.x.size()) +
                                  " x values and " + std::to_string(s.y.size()) + " y values");
    }
  }
}

std::pair<double, double> CheckedRange(const std::pair<double, double>& range,
                                       const std::string& what, const LineChart& chart) {
  if (!std::isfinite(range.first) || !std::isfinite(range.second) ||
      !(range.first < range.second)) {
    throw std::invalid_argument("line chart '" + chart.title + "': " + what +
                                " range is empty or not finite");
  }
  return range;
}

std::pair<double, double> XRange(const LineChart& chart) {
  if (chart.x_range) return CheckedRange(*chart.x_range, "x", chart);
  Extent extent;
  for (const ChartSeries& s : chart.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (std::isfinite(s.y[i])) extent.Add(s.x[i]);
    }
  }
  if (extent.empty()) CheckedRange({kInf, kInf}, "x", chart);
  return CheckedRange(PaddedRange(extent.lo, extent.hi, 0.0), "x", chart);
}

std::pair<double, double> YRange(const LineChart& chart, const ChartStyle& style) {
  if (chart.y_range) return CheckedRange(*chart.y_range, "y", chart);
  Extent extent;
  for (const ChartSeries& s : chart.series) {
    for (std::size_t i = 0; i < s.y.size(); ++i) {
      if (std::isfinite(s.x[i])) extent.Add(s.y[i]);
    }
  }
  for (const ChartLimitLine& line : chart.limit_lines) extent.Add(line.y);
  if (extent.empty()) CheckedRange({kInf, kInf}, "y", chart);
  return CheckedRange(PaddedRange(extent.lo, extent.hi, style.y_padding), "y", chart);
}

int HeaderHeight(const ChartStyle& s) { return (BitmapFont::kLineHeight + 4) * s.text_scale; }
int TickLength(const ChartStyle& s) { return 3 * s.text_scale; }

int FooterHeight(const LineChart& chart, const ChartStyle& s) {
  const int ticks = TickLength(s) + 2 * s.text_scale + BitmapFont::TextHeight(s.text_scale);
  const int label = chart.x_label.empty() ? 0 : BitmapFont::kLineHeight * s.text_scale + 2;
  return ticks + label + 3 * s.text_scale;
}

// Liang-Barsky: clips segment a-b to the rectangle; false if nothing is left.
bool ClipSegment(const PixelRect& r, Eigen::Vector2d* a, Eigen::Vector2d* b) {
  const Eigen::Vector2d d = *b - *a;
  double t0 = 0.0, t1 = 1.0;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a->x() - r.x0, r.x1 - a->x(), a->y() - r.y0, r.y1 - a->y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  const Eigen::Vector2d start = *a;
  *a = start + t0 * d;
  *b = start + t1 * d;
  return true;
}

// The series in pixels, clipped to the plot; NaN points separate the visible pieces.
std::vector<Eigen::Vector2d> ClippedPolyline(const ChartSeries& s, const ChartLayout& layout) {
  const Eigen::Vector2d gap = Eigen::Vector2d::Constant(std::nan(""));
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i + 1 < s.x.size(); ++i) {
    Eigen::Vector2d a = layout.ToPixel(s.x[i], s.y[i]);
    Eigen::Vector2d b = layout.ToPixel(s.x[i + 1], s.y[i + 1]);
    if (!a.allFinite() || !b.allFinite() || !ClipSegment(layout.plot, &a, &b)) {
      out.push_back(gap);
      continue;
    }
    if (out.empty() || !out.back().allFinite() || (out.back() - a).norm() > 1e-9) {
      out.push_back(gap);
      out.push_back(a);
    }
    out.push_back(b);
  }
  return out;
}

void DrawGridAndTicks(Image* image, const ChartLayout& l, const ChartStyle& s) {
  const PixelRect& p = l.plot;
  const int scale = s.text_scale;
  const int glyph_h = BitmapFont::TextHeight(scale);
  for (double x : l.x_ticks) {
    const int u = static_cast<int>(std::lround(l.ToPixel(x, l.y_min).x()));
    FillRect(image, u, p.y0, u + 1, p.y1, s.grid);
    FillRect(image, u, p.y1, u + 1, p.y1 + TickLength(s), s.frame);
    const std::string text = FormatTick(x, l.x_step);
    DrawText(image, u - BitmapFont::TextWidth(text, scale) / 2, p.y1 + TickLength(s) + 2 * scale,
             text, colors::kInk, scale);
  }
  for (double y : l.y_ticks) {
    const int v = static_cast<int>(std::lround(l.ToPixel(l.x_min, y).y()));
    FillRect(image, p.x0, v, p.x1, v + 1, s.grid);
    FillRect(image, p.x0 - TickLength(s), v, p.x0, v + 1, s.frame);
    const std::string text = FormatTick(y, l.y_step);
    DrawText(image, p.x0 - TickLength(s) - 2 * scale - BitmapFont::TextWidth(text, scale),
             v - glyph_h / 2, text, colors::kInk, scale);
  }
}

// The dashed lines (labels: false) or their labels (true), for the limits inside the y range.
void DrawLimitLines(Image* image, const LineChart& chart, const ChartLayout& l, const ChartStyle& s,
                    bool labels) {
  const PixelRect& p = l.plot;
  const int scale = s.text_scale;
  for (const ChartLimitLine& line : chart.limit_lines) {
    if (!(line.y >= l.y_min && line.y <= l.y_max)) continue;
    const double v = l.ToPixel(l.x_min, line.y).y();
    if (!labels) {
      DrawDashedLine(image, {p.x0 + 1.0, v}, {p.x1 - 1.0, v}, line.colour, line.width_px,
                     line.dash);
      continue;
    }
    if (line.label.empty()) continue;
    const int w = BitmapFont::TextWidth(line.label, scale);
    const int h = BitmapFont::TextHeight(scale);
    const int x = p.x1 - w - 3 * scale;
    int y = static_cast<int>(std::lround(v)) - h - 3 * scale;                // above the line...
    if (y < p.y0 + scale) y = static_cast<int>(std::lround(v)) + 3 * scale;  // ...or below
    FillRect(image, x - scale, y - scale, x + w + scale, y + h + scale, s.background, 0.8);
    DrawText(image, x, y, line.label, line.colour, scale);
  }
}

void DrawHeader(Image* image, const PixelRect& area, const LineChart& chart, const ChartLayout& l,
                const ChartStyle& s) {
  const int scale = s.text_scale;
  const int y = area.y0 + 2 * scale;
  int x = l.plot.x0;
  if (!chart.title.empty()) {
    DrawText(image, x, y, chart.title, colors::kInk, scale);
    x += BitmapFont::TextWidth(chart.title, scale) + 3 * BitmapFont::kAdvance * scale;
  }
  if (!chart.y_label.empty()) DrawText(image, x, y, chart.y_label, colors::kInk, scale);
  if (!chart.show_legend) return;
  // Legend, right-aligned: a short line in the series' colour, then its label.
  const int key = 4 * BitmapFont::kAdvance * scale / 2;
  const int gap = 2 * BitmapFont::kAdvance * scale;
  int right = l.plot.x1;
  for (auto it = chart.series.rbegin(); it != chart.series.rend(); ++it) {
    if (it->label.empty()) continue;
    const int w = BitmapFont::TextWidth(it->label, scale);
    const int left = right - w - key - scale * 2;
    const double mid = y + BitmapFont::TextHeight(scale) / 2.0;
    DrawLine(image, {left + 0.0, mid}, {left + key + 0.0, mid}, it->colour, it->width_px + 1.0);
    DrawText(image, left + key + 2 * scale, y, it->label, colors::kInk, scale);
    right = left - gap;
  }
}

void DrawFrame(Image* image, const PixelRect& p, const ChartStyle& s) {
  FillRect(image, p.x0 - 1, p.y0 - 1, p.x1 + 1, p.y0, s.frame);
  FillRect(image, p.x0 - 1, p.y1, p.x1 + 1, p.y1 + 1, s.frame);
  FillRect(image, p.x0 - 1, p.y0 - 1, p.x0, p.y1 + 1, s.frame);
  FillRect(image, p.x1, p.y0 - 1, p.x1 + 1, p.y1 + 1, s.frame);
}

}  // namespace

Eigen::Vector2d ChartLayout::ToPixel(double x, double y) const {
  return {plot.x0 + (x - x_min) / (x_max - x_min) * plot.width(),
          plot.y1 - (y - y_min) / (y_max - y_min) * plot.height()};
}

ChartLayout LayOutLineChart(const PixelRect& area, const LineChart& chart,
                            const ChartStyle& style) {
  CheckSeries(chart);
  if (style.text_scale < 1 || style.text_scale > 8) {
    throw std::invalid_argument("line chart '" + chart.title + "': text_scale " +
                                std::to_string(style.text_scale) + " is outside [1, 8]");
  }
  ChartLayout l;
  std::tie(l.x_min, l.x_max) = XRange(chart);
  std::tie(l.y_min, l.y_max) = YRange(chart, style);
  l.x_step = NiceTickStep(l.x_max - l.x_min, std::max(style.target_x_ticks, 1));
  l.y_step = NiceTickStep(l.y_max - l.y_min, std::max(style.target_y_ticks, 1));
  l.x_ticks = TicksIn(l.x_min, l.x_max, l.x_step);
  l.y_ticks = TicksIn(l.y_min, l.y_max, l.y_step);

  const int scale = style.text_scale;
  int label_w = 0;
  for (double y : l.y_ticks) {
    label_w = std::max(label_w, BitmapFont::TextWidth(FormatTick(y, l.y_step), scale));
  }
  int last_x_label_w = 0;
  for (double x : l.x_ticks) {
    last_x_label_w =
        std::max(last_x_label_w, BitmapFont::TextWidth(FormatTick(x, l.x_step), scale));
  }
  l.plot.x0 = area.x0 + (style.plot_left_inset_px > 0 ? style.plot_left_inset_px
                                                      : label_w + TickLength(style) + 4 * scale);
  l.plot.x1 = area.x1 - std::max(last_x_label_w / 2 + 2 * scale, 4 * scale);
  l.plot.y0 = area.y0 + HeaderHeight(style);
  l.plot.y1 = area.y1 - FooterHeight(chart, style);
  if (l.plot.width() < 10 || l.plot.height() < 10) {
    throw std::invalid_argument("line chart '" + chart.title + "': area " +
                                std::to_string(area.width()) + " x " +
                                std::to_string(area.height()) + " px is too small");
  }
  return l;
}

ChartLayout DrawLineChart(Image* image, const PixelRect& area, const LineChart& chart,
                          const ChartStyle& style) {
  const ChartLayout l = LayOutLineChart(area, chart, style);
  FillRect(image, area.x0, area.y0, area.x1, area.y1, style.background);
  DrawGridAndTicks(image, l, style);
  DrawLimitLines(image, chart, l, style, /*labels=*/false);
  for (const ChartSeries& s : chart.series) {
    const std::vector<Eigen::Vector2d> points = ClippedPolyline(s, l);
    DrawLongPolyline(image, points, s.colour, s.width_px);
  }
  DrawLimitLines(image, chart, l, style, /*labels=*/true);
  DrawFrame(image, l.plot, style);
  DrawHeader(image, area, chart, l, style);
  if (!chart.x_label.empty()) {
    const int scale = style.text_scale;
    const int w = BitmapFont::TextWidth(chart.x_label, scale);
    const int y = l.plot.y1 + TickLength(style) + 2 * scale + BitmapFont::TextHeight(scale) + 3;
    DrawText(image, (l.plot.x0 + l.plot.x1 - w) / 2, y, chart.x_label, colors::kInk, scale);
  }
  return l;
}

}  // namespace topay::viz
