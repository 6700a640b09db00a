#pragma once

// The 2D occupancy grid in the world xy plane, for the mobile base: OccupancyGrid<2>
// (core/map/occupancy_grid.h, one implementation with the 3D grid), and HeightBand.
#include "core/map/occupancy_grid.h"
#include "core/map/occupancy_grid3.h"

namespace topay {

using OccupancyGrid2 = OccupancyGrid<2>;

}  // namespace topay
