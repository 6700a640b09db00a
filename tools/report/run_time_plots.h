#pragma once
// time_plots.png: stacked panels over the run sharing one time axis: planned vs measured v
// (m/s), omega (rad/s) and each joint (rad), trajectory switches marked by vertical lines.

#include <string>
#include <vector>

#include "tools/report/run_time_series.h"
#include "tools/viz/image.h"
#include "tools/viz/line_chart.h"

namespace topay::report {

struct RunTimePlotOptions {
  std::string title;            ///< first line of the image, e.g. the log's path
  int width_px = 1200;
  int panel_height_px = 160;    ///< each of v, omega and the joints
  viz::ChartStyle style{.font_px = 13.0};
};

/// The panels' areas: a title of two lines, then 2 + joints panels (v, omega, q1..qN).
std::vector<viz::PixelRect> RunTimePlotPanels(int num_joints, const RunTimePlotOptions& options);

/// The image: width_px wide, RunTimePlotPanels().back().y1 + 4 high. With fewer than two
/// samples (no ROBOT_STATE to speak of) one panel says so. Throws std::invalid_argument for a
/// width outside [200, 16384] or a panel height under 60 px.
viz::Image RenderRunTimePlots(const RunTimeSeries& series, const RunTimePlotOptions& options = {});

}  // namespace topay::report
