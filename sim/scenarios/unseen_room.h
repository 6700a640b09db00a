#pragma once
// The room of a closed-loop run: a generated Tables room the robot has never seen, with
// nothing near the start (the origin, where topay-sim puts the robot).

#include <cstdint>

#include "sim/scenes/generated_scene.h"

namespace topay {

/// The Tables room of `seed` (GenerateTablesScene, default options) with no obstacle within
/// keep_out_radius_m of the origin (a vertical cylinder 3 m high): the same boxes as
/// `topay-sim --scene tables --seed <seed>` with scene.keep_out_radius_m. Throws
/// std::invalid_argument for a radius that is not finite and >= 0, std::runtime_error
/// (naming the seed) if the generator fails.
GeneratedScene UnseenTablesRoom(std::uint64_t seed, double keep_out_radius_m);

}  // namespace topay
