#pragma once

#include <vector>

#include "tools/viz/color.h"
#include "tools/viz/painter.h"
#include "tools/viz/view_transform.h"

namespace topay::viz {

/// How the metric axes around a top-down map look.
struct MapAxesStyle {
  double font_px = 12.0;
  double tick_px = 5.0;
  /// Labelled ticks about this far apart (px): the step is the NiceTickStep (1, 2, 5 x 10^k m)
  /// giving about view width / this many intervals.
  double tick_spacing_px = 60.0;
  Rgb colour = colors::kInk;
};

/// The labelled coordinates (m) along x and y: every multiple of step_m inside the view's
/// region, the same step on both axes.
struct MapTicks {
  double step_m = 1.0;
  std::vector<double> x_m;
  std::vector<double> y_m;
};
MapTicks MapAxisTicks(const ViewTransform& view, const MapAxesStyle& style = {});

/// A frame around the view's block; ticks pointing out of it at MapAxisTicks on all four sides;
/// their coordinates in metres below the bottom edge and left of the left edge; "x (m)" under
/// the x labels and "y (m)" (reading upwards) left of the y labels. Needs about
/// MapAxesLeftPx() left of the block and MapAxesBottomPx() below it.
void DrawMapAxes(Painter* painter, const ViewTransform& view, const MapAxesStyle& style = {});

/// Room the axes take beside the block: tick, labels of up to 5 characters, title.
double MapAxesLeftPx(const MapAxesStyle& style = {});
double MapAxesBottomPx(const MapAxesStyle& style = {});

}  // namespace topay::viz
