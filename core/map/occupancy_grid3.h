#pragma once

// The 3D occupancy grid of the world: OccupancyGrid<3> (core/map/occupancy_grid.h, one
// implementation with the 2D grid).
#include "core/map/occupancy_grid.h"

namespace topay {

using OccupancyGrid3 = OccupancyGrid<3>;

}  // namespace topay
