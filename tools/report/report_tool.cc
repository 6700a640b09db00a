#include "tools/report/report_tool.h"

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "sim/scenes/scene_json.h"
#include "tools/report/path_plot.h"
#include "tools/report/run_log.h"
#include "tools/report/run_time_series.h"
#include "tools/report/summary_json.h"
#include "tools/viz/png_io.h"

namespace topay::report {
namespace {

std::filesystem::path OutputDir(const ReportOptions& options) {
  std::filesystem::path dir = options.out_dir.empty() ? std::filesystem::path(options.log_path).parent_path()
                                                      : std::filesystem::path(options.out_dir);
  if (dir.empty()) dir = ".";
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw std::runtime_error(dir.string() + ": cannot create the output folder: " + error.message());
  return dir;
}

}  // namespace

RunSummary WriteReport(const ReportOptions& options) {
  const RunLog log = ReadRunLog(options.log_path);
  std::optional<Scene> scene;
  if (!options.scene_path.empty()) scene = ReadSceneJson(options.scene_path);
  const std::filesystem::path dir = OutputDir(options);
  RunSummary summary = Summarize(log);
  summary.files = {(dir / "summary.json").string(), (dir / "path.png").string(), (dir / "time_plots.png").string()};
  viz::WritePng(RenderPathPlot(log, scene ? &*scene : nullptr, options.path_plot), summary.files.path_png);
  RunTimePlotOptions time_plots = options.time_plots;
  if (time_plots.title.empty()) time_plots.title = options.log_path;
  viz::WritePng(RenderRunTimePlots(SampleRunTimeSeries(log), time_plots), summary.files.time_plots_png);
  WriteSummaryJson(summary, summary.files.summary_json);
  if (!options.json_path.empty()) WriteSummaryJson(summary, options.json_path);
  return summary;
}

}  // namespace topay::report
