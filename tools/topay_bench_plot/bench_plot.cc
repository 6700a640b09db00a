#include "tools/topay_bench_plot/bench_plot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "tools/viz/color_map.h"
#include "tools/viz/line_chart.h"
#include "tools/viz/painter.h"
#include "tools/viz/png_io.h"

namespace topay::bench_plot {
namespace {

using Json = nlohmann::json;

constexpr double kFontPx = 13.0;
// The bounds on an input file (a run of 100,000 tasks stays far below them).
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{512} << 20;

std::ifstream OpenInput(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(path + ": cannot read: not a regular file");
  }
  if (std::filesystem::file_size(path, error) > kMaxFileBytes) {
    throw InputError(path + ": larger than 512 MiB");
  }
  std::ifstream file(path);
  if (!file) throw InputError(path + ": cannot read");
  return file;
}

template <typename T>
T Field(const Json& json, const char* key, const std::string& where) {
  if (!json.is_object() || !json.contains(key)) throw InputError(where + ": missing " + key);
  try {
    return json.at(key).get<T>();
  } catch (const Json::exception&) {
    throw InputError(where + ": " + key + " has the wrong type");
  }
}

std::vector<SummaryEntry> ReadSummary(const std::string& path) {
  std::ifstream file = OpenInput(path);
  Json json;
  try {
    json = Json::parse(file);
  } catch (const Json::parse_error& e) {
    throw InputError(path + ": malformed JSON: " + e.what());
  }
  if (!json.is_array()) throw InputError(path + ": expected a JSON array of method objects");
  std::vector<SummaryEntry> entries;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const std::string where = path + ": entry " + std::to_string(i);
    entries.push_back({Field<std::string>(json[i], "method", where),
                       Field<std::string>(json[i], "scene", where),
                       Field<std::string>(json[i], "range", where),
                       Field<int>(json[i], "tasks", where),
                       Field<double>(json[i], "success_rate", where)});
  }
  return entries;
}

TaskLine ParseLine(const Json& json, const std::string& where) {
  TaskLine line;
  line.scene = Field<std::string>(json, "scene", where);
  line.range = Field<std::string>(json, "range", where);
  line.method = Field<std::string>(json, "method", where);
  line.success = Field<bool>(json, "success", where);
  line.total_ms = Field<double>(Field<Json>(json, "timings_ms", where), "total",
                                where + ": timings_ms");
  if (!json.contains("duration_s")) throw InputError(where + ": missing duration_s");
  if (!json.at("duration_s").is_null()) line.duration_s = Field<double>(json, "duration_s", where);
  line.base_distance_m = Field<double>(json, "base_distance_m", where);
  return line;
}

std::vector<TaskLine> ReadLines(const std::string& path) {
  std::ifstream file = OpenInput(path);
  std::vector<TaskLine> lines;
  std::string text;
  for (int number = 1; std::getline(file, text); ++number) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(number);
    Json json;
    try {
      json = Json::parse(text);
    } catch (const Json::parse_error& e) {
      throw InputError(where + ": malformed JSON: " + e.what());
    }
    lines.push_back(ParseLine(json, where));
  }
  return lines;
}

// Unique values in first-seen order.
template <typename T, typename Key>
std::vector<Key> Ordered(const std::vector<T>& items, Key (*key)(const T&)) {
  std::vector<Key> seen;
  for (const T& item : items) {
    const Key k = key(item);
    if (std::find(seen.begin(), seen.end(), k) == seen.end()) seen.push_back(k);
  }
  return seen;
}

using Cell = std::pair<std::string, std::string>;
template <typename T>
Cell CellOf(const T& item) {
  return {item.scene, item.range};
}
template <typename T>
std::string MethodOf(const T& item) {
  return item.method;
}

std::string CellName(const Cell& cell) { return cell.first + ", " + cell.second; }

viz::ChartStyle Style() {
  viz::ChartStyle style;
  style.font_px = kFontPx;
  return style;
}

// A legend entry for a method (a thick key in its colour, no points).
viz::ChartSeries Key(const std::string& label, const viz::Rgb& colour) {
  viz::ChartSeries key;
  key.label = label;
  key.colour = colour;
  key.width_px = 6.0;
  return key;
}

double Quantile(const std::vector<double>& sorted, double q) {
  const double position = q * (sorted.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(position));
  if (i + 1 >= sorted.size()) return sorted.back();
  return sorted[i] + (position - i) * (sorted[i + 1] - sorted[i]);
}

void DrawBox(viz::Painter* painter, const viz::ChartLayout& layout, double x, double half_width,
             const BoxStats& stats, const viz::Rgb& colour) {
  auto at = [&](double dx, double y) { return layout.ToPixel(x + dx, y); };
  const Eigen::Vector2d top_left = at(-half_width, stats.q3);
  const Eigen::Vector2d bottom_right = at(half_width, stats.q1);
  painter->FillRect(top_left.x(), top_left.y(), bottom_right.x(), bottom_right.y(),
                    viz::Lerp(colour, viz::colors::kWhite, 0.6));
  painter->StrokeRect(top_left.x(), top_left.y(), bottom_right.x(), bottom_right.y(), colour,
                      1.5);
  painter->DrawLine(at(-half_width, stats.median), at(half_width, stats.median),
                    viz::colors::kInk, 2.0);
  painter->DrawLine(at(0, stats.q3), at(0, stats.whisker_high), colour, 1.5);
  painter->DrawLine(at(0, stats.q1), at(0, stats.whisker_low), colour, 1.5);
  for (double y : {stats.whisker_low, stats.whisker_high}) {
    painter->DrawLine(at(-0.5 * half_width, y), at(0.5 * half_width, y), colour, 1.5);
  }
  for (double y : stats.outliers) painter->StrokeCircle(at(0, y), 3.0, colour, 1.0);
}

void DrawPlanningTimePanel(viz::Painter* painter, const viz::PixelRect& area, const Cell& cell,
                           const std::vector<std::string>& methods,
                           const std::vector<TaskLine>& lines) {
  std::vector<std::vector<double>> times(methods.size());
  double high = 1.0;
  for (const TaskLine& line : lines) {
    if (!line.success || CellOf(line) != cell) continue;
    const auto m = std::find(methods.begin(), methods.end(), line.method) - methods.begin();
    times[m].push_back(line.total_ms);
    high = std::max(high, line.total_ms);
  }
  viz::LineChart chart;
  chart.title = CellName(cell);
  chart.y_label = "T.P. (ms), successes";
  chart.x_range = std::make_pair(0.5, methods.size() + 0.5);
  chart.y_range = std::make_pair(0.0, 1.08 * high);
  for (std::size_t m = 0; m < methods.size(); ++m) {
    chart.x_tick_labels.emplace_back(m + 1.0, methods[m] + " (" +
                                                  std::to_string(times[m].size()) + ")");
  }
  viz::ChartStyle style = Style();
  style.target_y_ticks = 6;
  const viz::ChartLayout layout = viz::DrawLineChart(painter, area, chart, style);
  painter->PushClip(layout.plot.x0, layout.plot.y0, layout.plot.x1, layout.plot.y1);
  for (std::size_t m = 0; m < methods.size(); ++m) {
    // A method without a success keeps its column, empty.
    if (times[m].empty()) continue;
    DrawBox(painter, layout, m + 1.0, 0.25, ComputeBoxStats(times[m]),
            viz::CategoryColour(static_cast<int>(m)));
  }
  painter->PopClip();
}

}  // namespace

BenchRuns ReadBenchRuns(const std::vector<std::string>& run_dirs) {
  BenchRuns runs;
  for (const std::string& dir : run_dirs) {
    const std::filesystem::path folder(dir);
    std::vector<SummaryEntry> summaries = ReadSummary((folder / "summary.json").string());
    std::vector<TaskLine> lines = ReadLines((folder / "tasks.jsonl").string());
    runs.summaries.insert(runs.summaries.end(), summaries.begin(), summaries.end());
    runs.lines.insert(runs.lines.end(), lines.begin(), lines.end());
  }
  return runs;
}

BoxStats ComputeBoxStats(std::vector<double> values) {
  BoxStats stats;
  if (values.empty()) return stats;
  std::sort(values.begin(), values.end());
  stats.q1 = Quantile(values, 0.25);
  stats.median = Quantile(values, 0.5);
  stats.q3 = Quantile(values, 0.75);
  const double reach = 1.5 * (stats.q3 - stats.q1);
  stats.whisker_low = stats.q1;
  stats.whisker_high = stats.q3;
  for (double v : values) {
    if (v < stats.q1 - reach || v > stats.q3 + reach) {
      stats.outliers.push_back(v);
      continue;
    }
    stats.whisker_low = std::min(stats.whisker_low, v);
    stats.whisker_high = std::max(stats.whisker_high, v);
  }
  return stats;
}

viz::Image RenderSuccessRate(const std::vector<SummaryEntry>& summaries) {
  const std::vector<Cell> cells = Ordered(summaries, &CellOf<SummaryEntry>);
  const std::vector<std::string> methods = Ordered(summaries, &MethodOf<SummaryEntry>);
  const int width = std::max(600, 180 * static_cast<int>(cells.size()) + 120);
  viz::Image image(width, 420, viz::colors::kWhite);
  viz::Painter painter(&image);
  viz::LineChart chart;
  chart.title = "Success rate per scene and range";
  chart.y_label = "%";
  chart.x_range = std::make_pair(-0.5, cells.size() - 0.5);
  chart.y_range = std::make_pair(0.0, 112.0);
  chart.y_step = 20.0;
  chart.show_legend = true;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    chart.x_tick_labels.emplace_back(c, cells[c].first + "\n" + cells[c].second);
  }
  for (std::size_t m = 0; m < methods.size(); ++m) {
    chart.series.push_back(Key(methods[m], viz::CategoryColour(static_cast<int>(m))));
  }
  const viz::ChartLayout layout =
      viz::DrawLineChart(&painter, {0, 0, width, image.height()}, chart, Style());
  const double bar = 0.8 / std::max<std::size_t>(methods.size(), 1);
  for (const SummaryEntry& s : summaries) {
    const auto c = std::find(cells.begin(), cells.end(), CellOf(s)) - cells.begin();
    const auto m = std::find(methods.begin(), methods.end(), s.method) - methods.begin();
    const double x = c + (m - 0.5 * (methods.size() - 1)) * bar;
    const Eigen::Vector2d top = layout.ToPixel(x - 0.5 * bar, 100.0 * s.success_rate);
    const Eigen::Vector2d bottom = layout.ToPixel(x + 0.5 * bar, 0.0);
    painter.FillRect(std::round(top.x()) + 1, std::round(top.y()), std::round(bottom.x()) - 1,
                     std::round(bottom.y()), viz::CategoryColour(static_cast<int>(m)));
  }
  return image;
}

viz::Image RenderPlanningTime(const std::vector<TaskLine>& lines) {
  const std::vector<Cell> cells = Ordered(lines, &CellOf<TaskLine>);
  const std::vector<std::string> methods = Ordered(lines, &MethodOf<TaskLine>);
  const int panel = 420;
  viz::Image image(panel * std::max<int>(static_cast<int>(cells.size()), 1), 420,
                   viz::colors::kWhite);
  viz::Painter painter(&image);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const int x0 = panel * static_cast<int>(c);
    DrawPlanningTimePanel(&painter, {x0, 0, x0 + panel, image.height()}, cells[c], methods,
                          lines);
  }
  return image;
}

viz::Image RenderDurationVsDistance(const std::vector<TaskLine>& lines) {
  const std::vector<std::string> methods = Ordered(lines, &MethodOf<TaskLine>);
  viz::Image image(640, 480, viz::colors::kWhite);
  viz::Painter painter(&image);
  viz::LineChart chart;
  chart.title = "Trajectory duration vs distance (successes)";
  chart.y_label = "T.D. (s)";
  chart.x_label = "straight-line base distance (m)";
  chart.show_legend = true;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    viz::ChartSeries series;
    series.colour = viz::CategoryColour(static_cast<int>(m));
    series.marker_radius_px = 3.5;
    for (const TaskLine& line : lines) {
      if (line.method != methods[m] || !line.success || !line.duration_s) continue;
      series.x.push_back(line.base_distance_m);
      series.y.push_back(*line.duration_s);
    }
    series.label = methods[m] + " (" + std::to_string(series.x.size()) + ")";
    chart.series.push_back(series);
  }
  bool any = false;
  for (const viz::ChartSeries& s : chart.series) any = any || !s.x.empty();
  if (!any) {  // Nothing succeeded: an empty frame rather than an error.
    chart.x_range = std::make_pair(0.0, 1.0);
    chart.y_range = std::make_pair(0.0, 1.0);
  }
  viz::DrawLineChart(&painter, {0, 0, image.width(), image.height()}, chart, Style());
  return image;
}

void WriteBenchPlots(const BenchRuns& runs, const std::string& out_dir) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error || !std::filesystem::is_directory(out_dir)) {
    throw std::runtime_error(out_dir + ": cannot create the output folder");
  }
  const std::filesystem::path dir(out_dir);
  viz::WritePng(RenderSuccessRate(runs.summaries), (dir / "success_rate.png").string());
  viz::WritePng(RenderPlanningTime(runs.lines), (dir / "planning_time.png").string());
  viz::WritePng(RenderDurationVsDistance(runs.lines),
                (dir / "duration_vs_distance.png").string());
}

}  // namespace topay::bench_plot
