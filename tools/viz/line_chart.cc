#include "tools/viz/line_chart.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "tools/viz/chart_ticks.h"

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

std::pair<double, double> XRange(const LineChart& chart, const ChartStyle& style) {
  if (chart.x_range) return CheckedRange(*chart.x_range, "x", chart);
  Extent extent;
  for (const ChartSeries& s : chart.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (std::isfinite(s.y[i])) extent.Add(s.x[i]);
    }
  }
  if (extent.empty()) CheckedRange({kInf, kInf}, "x", chart);
  // Dots are not cut by the frame: scatter plots get the y padding on x too.
  bool markers = false;
  for (const ChartSeries& s : chart.series) markers = markers || s.marker_radius_px > 0.0;
  return CheckedRange(PaddedRange(extent.lo, extent.hi, markers ? style.y_padding : 0.0), "x",
                      chart);
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

double HeaderHeight(const ChartStyle& s) { return LineHeight(s.font_px) + 0.4 * s.font_px; }
double TickLength(const ChartStyle& s) { return 0.35 * s.font_px; }

double FooterHeight(const LineChart& chart, const ChartStyle& s) {
  const double ticks = TickLength(s) + 0.2 * s.font_px + LineHeight(s.font_px);
  const double label = chart.x_label.empty() ? 0.0 : LineHeight(s.font_px);
  return ticks + label + 0.3 * s.font_px;
}

// The x ticks to draw: the named ones inside the range, or the numeric ones.
std::vector<std::pair<double, std::string>> XTickLabels(const LineChart& chart,
                                                        const ChartLayout& l) {
  std::vector<std::pair<double, std::string>> ticks;
  if (!chart.x_tick_labels.empty()) {
    for (const auto& tick : chart.x_tick_labels) {
      if (tick.first >= l.x_min && tick.first <= l.x_max) ticks.push_back(tick);
    }
    return ticks;
  }
  for (double x : l.x_ticks) ticks.emplace_back(x, FormatTick(x, l.x_step));
  return ticks;
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

void DrawGridAndTicks(Painter* painter, const LineChart& chart, const ChartLayout& l,
                      const ChartStyle& s) {
  const PixelRect& p = l.plot;
  const double f = s.font_px;
  for (const auto& [x, text] : XTickLabels(chart, l)) {
    const double u = std::round(l.ToPixel(x, l.y_min).x()) + 0.5;
    painter->DrawLine({u, p.y0 + 0.0}, {u, p.y1 + 0.0}, s.grid, 1.0);
    painter->DrawLine({u, p.y1 + 1.0}, {u, p.y1 + 1.0 + TickLength(s)}, s.frame, 1.0);
    // Named ticks may span lines ("tables\nmedium").
    double y = p.y1 + TickLength(s) + 0.2 * f;
    std::size_t begin = 0;
    while (begin <= text.size()) {
      const std::size_t end = std::min(text.find('\n', begin), text.size());
      painter->Text(u, y, text.substr(begin, end - begin), colors::kInk, f, TextAlign::kCentre);
      y += LineHeight(f);
      begin = end + 1;
    }
  }
  for (double y : l.y_ticks) {
    const double v = std::round(l.ToPixel(l.x_min, y).y()) + 0.5;
    painter->DrawLine({p.x0 + 0.0, v}, {p.x1 + 0.0, v}, s.grid, 1.0);
    painter->DrawLine({p.x0 - 1.0 - TickLength(s), v}, {p.x0 - 1.0, v}, s.frame, 1.0);
    painter->Text(p.x0 - TickLength(s) - 0.2 * f, v - 0.65 * f, FormatTick(y, l.y_step),
                  colors::kInk, f, TextAlign::kRight);
  }
}

// The dashed lines (labels: false) or their labels (true), for the limits inside the y range.
void DrawLimitLines(Painter* painter, const LineChart& chart, const ChartLayout& l,
                    const ChartStyle& s, bool labels) {
  const PixelRect& p = l.plot;
  const double f = s.font_px;
  for (const ChartLimitLine& line : chart.limit_lines) {
    if (!(line.y >= l.y_min && line.y <= l.y_max)) continue;
    const double v = l.ToPixel(l.x_min, line.y).y();
    if (!labels) {
      painter->DrawDashedLine({p.x0 + 1.0, v}, {p.x1 - 1.0, v}, line.colour, line.width_px,
                              line.dash);
      continue;
    }
    if (line.label.empty()) continue;
    const double w = TextWidth(line.label, f);
    const double x = p.x1 - w - 0.3 * f;
    double y = v - LineHeight(f) - 0.1 * f;        // above the line...
    if (y < p.y0) y = v + 0.1 * f;                 // ...or below
    painter->FillRect(x - 2.0, y, x + w + 2.0, y + LineHeight(f), s.background, 0.8);
    painter->Text(x, y, line.label, line.colour, f);
  }
}

void DrawSeries(Painter* painter, const ChartSeries& series, const ChartLayout& l) {
  if (series.marker_radius_px > 0.0) {
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      const Eigen::Vector2d p = l.ToPixel(series.x[i], series.y[i]);
      if (p.allFinite()) painter->FillCircle(p, series.marker_radius_px, series.colour);
    }
    return;
  }
  painter->DrawPolyline(ClippedPolyline(series, l), /*closed=*/false, series.colour,
                        series.width_px);
}

void DrawHeader(Painter* painter, const PixelRect& area, const LineChart& chart,
                const ChartLayout& l, const ChartStyle& s) {
  const double f = s.font_px;
  const double y = area.y0 + 0.2 * f;
  double x = l.plot.x0;
  if (!chart.title.empty()) {
    painter->Text(x, y, chart.title, colors::kInk, f);
    x += TextWidth(chart.title, f) + 2.0 * f;
  }
  if (!chart.y_label.empty()) painter->Text(x, y, chart.y_label, {90, 90, 90}, f);
  if (!chart.show_legend) return;
  // Legend, right-aligned: a short line (or a dot) in the series' colour, then its label.
  const double key = 1.6 * f;
  double right = l.plot.x1;
  for (auto it = chart.series.rbegin(); it != chart.series.rend(); ++it) {
    if (it->label.empty()) continue;
    const double w = TextWidth(it->label, f);
    const double left = right - w - key - 0.3 * f;
    const double mid = y + 0.65 * f;
    if (it->marker_radius_px > 0.0) {
      painter->FillCircle({left + 0.5 * key, mid}, it->marker_radius_px, it->colour);
    } else {
      // Round caps reach half the width past the ends: keep them inside the key.
      const double cap = 0.5 * (it->width_px + 1.0);
      painter->DrawLine({left + cap, mid}, {left + key - cap, mid}, it->colour,
                        it->width_px + 1.0);
    }
    painter->Text(left + key + 0.3 * f, y, it->label, colors::kInk, f);
    right = left - 1.2 * f;
  }
}

}  // namespace

Eigen::Vector2d ChartLayout::ToPixel(double x, double y) const {
  return {plot.x0 + (x - x_min) / (x_max - x_min) * plot.width(),
          plot.y1 - (y - y_min) / (y_max - y_min) * plot.height()};
}

ChartLayout LayOutLineChart(const PixelRect& area, const LineChart& chart,
                            const ChartStyle& style) {
  CheckSeries(chart);
  if (!(style.font_px >= 4.0 && style.font_px <= 64.0)) {
    throw std::invalid_argument("line chart '" + chart.title + "': font_px " +
                                std::to_string(style.font_px) + " is outside [4, 64]");
  }
  ChartLayout l;
  std::tie(l.x_min, l.x_max) = XRange(chart, style);
  std::tie(l.y_min, l.y_max) = YRange(chart, style);
  l.x_step = NiceTickStep(l.x_max - l.x_min, std::max(style.target_x_ticks, 1));
  l.y_step = chart.y_step && *chart.y_step > 0.0
                 ? *chart.y_step
                 : NiceTickStep(l.y_max - l.y_min, std::max(style.target_y_ticks, 1));
  l.x_ticks = TicksIn(l.x_min, l.x_max, l.x_step);
  l.y_ticks = TicksIn(l.y_min, l.y_max, l.y_step);

  const double f = style.font_px;
  double label_w = 0.0;
  for (double y : l.y_ticks) label_w = std::max(label_w, TextWidth(FormatTick(y, l.y_step), f));
  double last_x_label_w = 0.0;
  int x_label_lines = 1;
  for (const auto& [x, text] : XTickLabels(chart, l)) {
    last_x_label_w = std::max(last_x_label_w, TextWidth(text, f));
    x_label_lines = std::max(
        x_label_lines, 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n')));
  }
  if (!chart.x_tick_labels.empty()) last_x_label_w = 0.0;  // Categories sit inside the plot.
  l.plot.x0 = area.x0 + (style.plot_left_inset_px > 0
                             ? style.plot_left_inset_px
                             : static_cast<int>(std::ceil(label_w + TickLength(style) + 0.6 * f)));
  l.plot.x1 = area.x1 - static_cast<int>(std::ceil(std::max(last_x_label_w / 2 + 0.2 * f, 0.4 * f)));
  l.plot.y0 = area.y0 + static_cast<int>(std::ceil(HeaderHeight(style)));
  l.plot.y1 = area.y1 - static_cast<int>(std::ceil(FooterHeight(chart, style) +
                                                   (x_label_lines - 1) * LineHeight(f)));
  if (l.plot.width() < 10 || l.plot.height() < 10) {
    throw std::invalid_argument("line chart '" + chart.title + "': area " +
                                std::to_string(area.width()) + " x " +
                                std::to_string(area.height()) + " px is too small");
  }
  return l;
}

ChartLayout DrawLineChart(Painter* painter, const PixelRect& area, const LineChart& chart,
                          const ChartStyle& style) {
  const ChartLayout l = LayOutLineChart(area, chart, style);
  painter->FillRect(area.x0, area.y0, area.x1, area.y1, style.background);
  DrawGridAndTicks(painter, chart, l, style);
  DrawLimitLines(painter, chart, l, style, /*labels=*/false);
  painter->PushClip(l.plot.x0, l.plot.y0, l.plot.x1, l.plot.y1);
  for (const ChartSeries& s : chart.series) DrawSeries(painter, s, l);
  painter->PopClip();
  DrawLimitLines(painter, chart, l, style, /*labels=*/true);
  painter->StrokeRect(l.plot.x0 - 1, l.plot.y0 - 1, l.plot.x1 + 1, l.plot.y1 + 1, style.frame);
  DrawHeader(painter, area, chart, l, style);
  if (!chart.x_label.empty()) {
    const double f = style.font_px;
    const double y = area.y1 - LineHeight(f) - 0.2 * f;
    painter->Text(0.5 * (l.plot.x0 + l.plot.x1), y, chart.x_label, colors::kInk, f,
                  TextAlign::kCentre);
  }
  return l;
}

ChartLayout DrawLineChart(Image* image, const PixelRect& area, const LineChart& chart,
                          const ChartStyle& style) {
  Painter painter(image);
  return DrawLineChart(&painter, area, chart, style);
}

}  // namespace topay::viz
