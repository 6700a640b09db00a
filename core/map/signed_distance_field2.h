#pragma once

// The 2D signed distance field in the world xy plane, for the mobile base (built from an
// OccupancyGrid2, e.g. OccupancyGrid2::AddBoxInBand over the chassis band, or from exact
// footprint distances): SignedDistanceField<2> (core/map/signed_distance_field.h, one
// implementation with the 3D field).
#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_field.h"

namespace topay {

using SignedDistanceField2 = SignedDistanceField<2>;

}  // namespace topay
