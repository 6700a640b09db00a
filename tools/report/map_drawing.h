#pragma once
// The occupancy map from above: each column of the grid with an occupied voxel, filled with
// the grey of its highest occupied voxel's top (taller is darker).

#include "tools/report/run_log.h"
#include "tools/viz/color_map.h"
#include "tools/viz/world_canvas.h"

namespace topay::report {

/// The heights (m) the grey ramp spans: the grid's z extent.
viz::ScalarRange MapHeightRange(const FinalMap& map);

/// The number of columns drawn (those with an occupied voxel).
int DrawOccupiedColumns(viz::WorldCanvas* canvas, const FinalMap& map);

}  // namespace topay::report
