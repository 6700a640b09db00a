#pragma once

// The 3D signed distance field of the world, for the arm: SignedDistanceField<3>
// (core/map/signed_distance_field.h, one implementation with the 2D field).
#include "core/map/occupancy_grid3.h"
#include "core/map/signed_distance_field.h"

namespace topay {

using SignedDistanceField3 = SignedDistanceField<3>;

}  // namespace topay
