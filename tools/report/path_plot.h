#pragma once
// path.png: the run from above. The occupancy map at the end of the run (occupied columns,
// grey by height), the scene's boxes as outlines (if the scene is given), every planned base
// path (thin, faded), the driven base path (bold), the boxes that appeared (highlighted), the
// contacts (red, where the base was), the start, the goals' targets and the arrivals; metric
// axes and a legend below.

#include "core/geometry/scene.h"
#include "tools/report/path_plot_view.h"
#include "tools/report/run_log.h"
#include "tools/viz/image.h"

namespace topay::report {

/// The image: PathPlotWidth wide; the map block is PathPlotView's, the legend below it.
/// `scene` may be null.
viz::Image RenderPathPlot(const RunLog& log, const Scene* scene, const PathPlotOptions& options = {});

}  // namespace topay::report
