#pragma once
// Starting the dense map from known voxels (a prior .bt, the map journal of a mapper that was
// restarted): each known voxel is set at a clamping bound of the sensor model (occupied at
// log_odds_max, free at log_odds_min), as OctoMap's .bt files keep only the maximum-likelihood
// state; unknown voxels stay as they are.

#include <cstdint>
#include <span>
#include <vector>

#include "core/map/occupancy_map.h"

namespace topay::mapper {

/// The states of a map's state bytes (OccupancyMap::states(), a message's or journal's grid).
std::vector<VoxelState> VoxelStatesOf(std::span<const std::uint8_t> bytes);

/// Sets each kOccupied / kFree voxel of `states` (one per voxel of map->geometry(), Index
/// order; std::invalid_argument for another count) in *map. Returns the number set.
std::int64_t SeedKnownVoxels(std::span<const VoxelState> states, OccupancyMap* map);

}  // namespace topay::mapper
