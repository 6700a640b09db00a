#include "tools/viz/time_plot.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "tools/viz/color_map.h"
#include "tools/viz/painter.h"

namespace topay::viz {
namespace {

constexpr Rgb kSeriesColour{0, 90, 181};
constexpr Rgb kLimitColour{200, 30, 30};
constexpr Rgb kCoupledColour{150, 150, 150};

std::string Number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void CheckData(const TimePlotData& data, const TimePlotLimits& limits) {
  const std::size_t n = data.t_s.size();
  if (n < 2) throw std::invalid_argument("time plot: fewer than 2 samples");
  auto check = [&](const std::vector<double>& values, const std::string& name) {
    if (values.size() != n) {
      throw std::invalid_argument("time plot: " + name + " has " + std::to_string(values.size()) +
                                  " samples, t_s has " + std::to_string(n));
    }
  };
  check(data.v_mps, "v_mps");
  check(data.omega_radps, "omega_radps");
  check(data.a_mps2, "a_mps2");
  check(data.beta_radps2, "beta_radps2");
  for (std::size_t k = 0; k < data.q_rad.size(); ++k) {
    check(data.q_rad[k], "q_rad[" + std::to_string(k) + "]");
  }
  const auto joints = static_cast<Eigen::Index>(data.q_rad.size());
  if (limits.q_min_rad.size() != joints || limits.q_max_rad.size() != joints) {
    throw std::invalid_argument("time plot: " + std::to_string(joints) +
                                " joint series but joint limits for " +
                                std::to_string(limits.q_min_rad.size()) + " / " +
                                std::to_string(limits.q_max_rad.size()) + " joints");
  }
  const BaseLimits& b = limits.base;
  for (double value : {b.v_max_mps, b.omega_max_radps, b.a_max_mps2, b.beta_max_radps2}) {
    if (!(std::isfinite(value) && value > 0.0)) {
      throw std::invalid_argument("time plot: base limits must be finite and > 0");
    }
  }
  if (!limits.q_min_rad.allFinite() || !limits.q_max_rad.allFinite()) {
    throw std::invalid_argument("time plot: joint limits must be finite");
  }
}

// A base quantity with its symmetric limit +-bound (dashed; said in the header).
LineChart BaseChart(const std::string& title, const std::string& unit, const std::string& symbol,
                    const std::vector<double>& t, const std::vector<double>& values, double bound) {
  LineChart chart;
  chart.title = title + " " + symbol + " (" + unit + ")";
  chart.y_label = "dashed: ±" + symbol + "_max = " + Number(bound) + " " + unit;
  chart.series.push_back({t, values, kSeriesColour, symbol, 2.0});
  ChartLimitLine upper;
  upper.y = bound;
  upper.colour = kLimitColour;
  ChartLimitLine lower = upper;
  lower.y = -bound;
  chart.limit_lines.push_back(upper);
  chart.limit_lines.push_back(lower);
  return chart;
}

// The v panel also shows the speed the coupled constraint leaves at each yaw rate (eq. (9):
// |v_max omega +- omega_max v| <= v_max omega_max, i.e. |v| <= v_max (1 - |omega| / omega_max)).
void AddCoupledSpeedBound(const TimePlotData& data, const BaseLimits& b, LineChart* chart) {
  ChartSeries upper;
  upper.x = data.t_s;
  upper.colour = kCoupledColour;
  upper.width_px = 1.5;
  for (double omega : data.omega_radps) {
    upper.y.push_back(b.v_max_mps * std::max(0.0, 1.0 - std::abs(omega) / b.omega_max_radps));
  }
  ChartSeries lower = upper;
  for (double& v : lower.y) v = -v;
  upper.label = "v bound from ω, eq. (9)";
  chart->series.insert(chart->series.begin(), {upper, lower});
  chart->show_legend = true;
}

LineChart JointChart(const TimePlotData& data, const TimePlotLimits& limits) {
  LineChart chart;
  chart.title = "joint angles q (rad)";
  chart.y_label = "dashed: joint limits";
  chart.x_label = "t (s)";
  chart.show_legend = true;
  for (std::size_t k = 0; k < data.q_rad.size(); ++k) {
    const int joint = static_cast<int>(k);
    chart.series.push_back(
        {data.t_s, data.q_rad[k], JointColour(joint), "q" + std::to_string(k + 1), 2.0});
    ChartLimitLine low{limits.q_min_rad(joint), JointColour(joint), "", 1.0, {6.0, 6.0}};
    ChartLimitLine high = low;
    high.y = limits.q_max_rad(joint);
    chart.limit_lines.push_back(low);
    chart.limit_lines.push_back(high);
  }
  return chart;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  if (lines.empty()) lines.emplace_back();
  return lines;
}

int TitleHeight(const TimePlotOptions& o) {
  const double f = o.style.font_px;
  return static_cast<int>(std::ceil(LineHeight(f) * Lines(o.title).size() + 0.6 * f));
}

}  // namespace

TimePlotData SampleTimePlotData(const ArcYawTrajectory& trajectory, double period_s) {
  if (!(period_s >= 1e-4 && period_s <= 10.0)) {
    throw std::invalid_argument("SampleTimePlotData: period " + Number(period_s) +
                                " s is outside [1e-4, 10] s");
  }
  if (!trajectory.minco().solved()) {
    throw std::invalid_argument("SampleTimePlotData: the trajectory has not been solved");
  }
  TimePlotData data;
  data.q_rad.assign(trajectory.num_joints(), {});
  TrajectorySample point = trajectory.MakePoint();
  const double end_s = trajectory.duration_s();
  auto add = [&](double t_s) {
    trajectory.Evaluate(t_s, &point);
    data.t_s.push_back(t_s);
    data.v_mps.push_back(point.v_mps);
    data.omega_radps.push_back(point.omega_radps);
    data.a_mps2.push_back(point.a_mps2);
    data.beta_radps2.push_back(point.beta_radps2);
    for (int k = 0; k < trajectory.num_joints(); ++k) {
      data.q_rad[k].push_back(point.state.q_rad(k));
    }
  };
  for (long k = 0;; ++k) {
    const double t_s = static_cast<double>(k) * period_s;
    if (t_s >= end_s - 1e-9) break;
    add(t_s);
  }
  add(end_s);
  return data;
}

Rgb JointColour(int joint) { return CategoryColour(joint); }

std::vector<LineChart> TimePlotCharts(const TimePlotData& data, const TimePlotLimits& limits) {
  CheckData(data, limits);
  const BaseLimits& b = limits.base;
  std::vector<LineChart> charts;
  charts.push_back(BaseChart("linear velocity", "m/s", "v", data.t_s, data.v_mps, b.v_max_mps));
  AddCoupledSpeedBound(data, b, &charts.back());
  charts.push_back(
      BaseChart("yaw rate", "rad/s", "ω", data.t_s, data.omega_radps, b.omega_max_radps));
  charts.push_back(
      BaseChart("linear acceleration", "m/s²", "a", data.t_s, data.a_mps2, b.a_max_mps2));
  charts.push_back(BaseChart("yaw acceleration", "rad/s²", "β", data.t_s, data.beta_radps2,
                             b.beta_max_radps2));
  charts.push_back(JointChart(data, limits));
  // One time axis for every panel.
  for (LineChart& chart : charts) chart.x_range = {data.t_s.front(), data.t_s.back()};
  return charts;
}

std::vector<PixelRect> TimePlotPanels(const TimePlotOptions& o) {
  std::vector<PixelRect> panels;
  int y = TitleHeight(o);
  for (int i = 0; i < 4; ++i) {
    panels.push_back({0, y, o.width_px, y + o.base_panel_height_px});
    y += o.base_panel_height_px;
  }
  panels.push_back({0, y, o.width_px, y + o.joint_panel_height_px});
  return panels;
}

Image RenderTimePlots(const TimePlotData& data, const TimePlotLimits& limits,
                      const TimePlotOptions& options) {
  if (options.width_px < 100 || options.width_px > Image::kMaxSidePx ||
      options.base_panel_height_px < 40 || options.joint_panel_height_px < 40) {
    throw std::invalid_argument(
        "time plot: width_px in [100, 16384] and panel heights >= 40 px needed");
  }
  std::vector<LineChart> charts = TimePlotCharts(data, limits);
  if (!(data.t_s.back() > data.t_s.front())) {
    throw std::invalid_argument("time plot: the samples span no time");
  }
  const std::vector<PixelRect> panels = TimePlotPanels(options);
  // One left inset for every panel (the widest one's), so the time axes line up.
  ChartStyle measure = options.style;
  measure.plot_left_inset_px = 0;
  ChartStyle style = options.style;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const ChartLayout layout = LayOutLineChart(panels[i], charts[i], measure);
    style.plot_left_inset_px = std::max(style.plot_left_inset_px, layout.plot.x0 - panels[i].x0);
  }
  Image image(options.width_px, panels.back().y1 + 4, style.background);
  Painter painter(&image);
  double y = 0.3 * style.font_px;
  for (const std::string& line : Lines(options.title)) {
    painter.Text(0.5 * style.font_px, y, line, colors::kInk, style.font_px);
    y += LineHeight(style.font_px);
  }
  for (std::size_t i = 0; i < charts.size(); ++i) {
    DrawLineChart(&painter, panels[i], charts[i], style);
  }
  return image;
}

}  // namespace topay::viz
