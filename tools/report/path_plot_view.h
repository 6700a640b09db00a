#pragma once
// Where path.png looks: the region that holds the room (the scene's bounds, else the map's),
// the driven path, the planned paths and the appeared boxes, at a scale that fits it into
// about target_map_px pixels.

#include "core/geometry/scene.h"
#include "tools/report/run_log.h"
#include "tools/viz/map_axes.h"
#include "tools/viz/view_transform.h"

namespace topay::report {

struct PathPlotOptions {
  double px_per_m = 0.0;     ///< scale of the map; <= 0: the region's longer side fits target_map_px
  int target_map_px = 1000;  ///< (clamped to 4..200 px per metre)
  double margin_m = 0.5;     ///< around the region, inside the axes
  double planned_sample_period_s = 0.05;  ///< base path samples of each trajectory
  double font_px = 13.0;     ///< legend text
  double right_px = 16.0;    ///< paper right of the map
  double top_px = 12.0;      ///< paper above the map
  viz::MapAxesStyle axes;
};

/// The xy region everything drawn lies in (before the margin); a 2 x 2 m square at the origin
/// when there is nothing.
Eigen::AlignedBox2d PathPlotRegion(const RunLog& log, const Scene* scene, const PathPlotOptions& options);

/// The map's view: the region plus margin at the scale, its top-left corner right of the y
/// axis's labels and below top_px.
viz::ViewTransform PathPlotView(const RunLog& log, const Scene* scene, const PathPlotOptions& options);

/// The image's width for the view: the y axis's room, the map, right_px.
int PathPlotWidth(const viz::ViewTransform& view, const PathPlotOptions& options);

}  // namespace topay::report
