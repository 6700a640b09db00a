#include "tools/report/run_time_plots.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tools/viz/painter.h"

namespace topay::report {
namespace {

constexpr viz::Rgb kPlanned{0, 90, 181};
constexpr viz::Rgb kMeasured{230, 120, 0};
constexpr viz::Rgb kSwitch{120, 120, 120};

int TitleHeight(const RunTimePlotOptions& o) {
  return static_cast<int>(std::ceil(2.0 * viz::LineHeight(o.style.font_px) + 0.6 * o.style.font_px));
}

viz::LineChart Panel(const std::string& title, const std::vector<double>& t, const std::vector<double>& planned,
                     const std::vector<double>& measured) {
  viz::LineChart chart;
  chart.title = title;
  chart.show_legend = true;
  chart.series.push_back({t, planned, kPlanned, "planned", 2.0});
  chart.series.push_back({t, measured, kMeasured, "measured", 1.5});
  chart.x_range = {t.front(), t.back()};
  const auto finite = [](const std::vector<double>& y) {
    return std::any_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); });
  };
  if (!finite(planned) && !finite(measured)) chart.y_range = {-1.0, 1.0};  // nothing to fit: an empty panel
  return chart;
}

std::vector<viz::LineChart> Panels(const RunTimeSeries& s) {
  std::vector<viz::LineChart> charts;
  charts.push_back(Panel("v (m/s)", s.t_s, s.v_planned_mps, s.v_measured_mps));
  charts.push_back(Panel("ω (rad/s)", s.t_s, s.omega_planned_radps, s.omega_measured_radps));
  for (std::size_t j = 0; j < s.q_measured_rad.size(); ++j) {
    charts.push_back(Panel("q" + std::to_string(j + 1) + " (rad)", s.t_s, s.q_planned_rad[j], s.q_measured_rad[j]));
  }
  charts.back().x_label = "t (s) since the first ROBOT_STATE";
  return charts;
}

// Dotted vertical lines at the switches, inside the plot.
void MarkSwitches(viz::Painter* painter, const viz::ChartLayout& layout, const std::vector<double>& switch_t_s) {
  for (double t : switch_t_s) {
    if (t < layout.x_min || t > layout.x_max) continue;
    const double x_px = std::floor(layout.ToPixel(t, layout.y_max).x()) + 0.5;  // on a pixel column: crisp
    const Eigen::Vector2d top(x_px, layout.plot.y0), bottom(x_px, layout.plot.y1);
    painter->DrawDashedLine(top, bottom, kSwitch, 1.0, {3.0, 3.0});
  }
}

void DrawTitle(viz::Painter* painter, const RunTimePlotOptions& o) {
  const double f = o.style.font_px;
  painter->Text(0.5 * f, 0.3 * f, o.title, viz::colors::kInk, f);
  painter->Text(0.5 * f, 0.3 * f + viz::LineHeight(f),
                "planned (blue): the active trajectory at each ROBOT_STATE; measured (orange): ROBOT_STATE; "
                "dotted: trajectory switches",
                viz::colors::kInk, f);
}

}  // namespace

std::vector<viz::PixelRect> RunTimePlotPanels(int num_joints, const RunTimePlotOptions& o) {
  std::vector<viz::PixelRect> panels;
  int y = TitleHeight(o);
  for (int i = 0; i < 2 + num_joints; ++i, y += o.panel_height_px) {
    panels.push_back({0, y, o.width_px, y + o.panel_height_px});
  }
  return panels;
}

viz::Image RenderRunTimePlots(const RunTimeSeries& series, const RunTimePlotOptions& o) {
  if (o.width_px < 200 || o.width_px > viz::Image::kMaxSidePx || o.panel_height_px < 60) {
    throw std::invalid_argument("run time plots: width_px in [200, 16384] and panel_height_px >= 60 needed");
  }
  const bool has_data = series.t_s.size() >= 2 && series.t_s.back() > series.t_s.front();
  const int joints = has_data ? static_cast<int>(series.q_measured_rad.size()) : -1;
  const std::vector<viz::PixelRect> panels = RunTimePlotPanels(joints, o);
  viz::Image image(o.width_px, panels.back().y1 + 4, o.style.background);
  viz::Painter painter(&image);
  DrawTitle(&painter, o);
  if (!has_data) {
    painter.Text(o.style.font_px, panels[0].y0 + o.style.font_px, "no motion to plot: fewer than two ROBOT_STATE",
                 viz::colors::kInk, o.style.font_px);
    return image;
  }
  const std::vector<viz::LineChart> charts = Panels(series);
  viz::ChartStyle style = o.style;  // one left inset (the widest), so the time axes line up
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const int inset = viz::LayOutLineChart(panels[i], charts[i], o.style).plot.x0 - panels[i].x0;
    style.plot_left_inset_px = std::max(style.plot_left_inset_px, inset);
  }
  for (std::size_t i = 0; i < charts.size(); ++i) {
    MarkSwitches(&painter, viz::DrawLineChart(&painter, panels[i], charts[i], style), series.switch_t_s);
  }
  return image;
}

}  // namespace topay::report
