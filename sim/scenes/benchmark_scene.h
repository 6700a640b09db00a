#pragma once

#include <cstdint>

#include "sim/scenes/generated_scene.h"
#include "sim/scenes/keep_out.h"
#include "sim/scenes/room_options.h"
#include "sim/scenes/scene_kind.h"

namespace topay {

// Seeded generators of the paper's benchmark rooms (Sec. IV-C, with the authors'
// code's figures). Same seed and options, same scene (every number on the 1e-6 grid, so the same
// JSON bytes). Boxes come in this order: 4 walls, then the objects in the order listed below.
// All obstacles have a random yaw, uniform in [-pi, pi) (the paper's figure shows rotated
// obstacles; the protocol does not say). No obstacle enters `keep_out`, and every obstacle's
// world AABB lies inside the walls. Overlaps between obstacles are allowed.
// Throws std::invalid_argument for bad options and std::runtime_error when an object cannot be
// placed (see RoomBuilder).

/// Cuboids: 80 grounded boxes (footprint U[0.2, 0.8]^2 m, height U[0.4, 1.5] m), then 80
/// floating cubes (side U[0.3, 0.6] m, bottom at U[0.4, 0.8] m).
GeneratedScene GenerateCuboidsScene(std::uint64_t seed, const KeepOutRegions& keep_out = {},
                                    const CuboidsOptions& options = {});

/// Tables: 40 groups of 1-2 x 1-2 adjacent tables (each table a top and four legs, see
/// TableGroupOptions), then 80 grounded boxes as in Cuboids.
GeneratedScene GenerateTablesScene(std::uint64_t seed, const KeepOutRegions& keep_out = {},
                                   const TablesOptions& options = {});

/// Either generator with default options.
GeneratedScene GenerateBenchmarkScene(SceneKind kind, std::uint64_t seed,
                                      const KeepOutRegions& keep_out = {});

}  // namespace topay
