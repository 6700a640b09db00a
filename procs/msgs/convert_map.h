#pragma once
// map_update_t <-> the core's 3D occupancy grid (core/map).

#include <cstdint>
#include <optional>
#include <string>

#include "core/map/occupancy_grid.h"
#include "topay/map_update_t.hpp"

namespace topay::msgs {

/// A full snapshot of `grid` (is_full, every voxel FREE or OCCUPIED; the grid has no unknown).
map_update_t ToFullMapMessage(const OccupancyGrid<3>& grid, std::int64_t utime,
                              std::int64_t map_seq);

/// The grid of a full snapshot. UNKNOWN voxels become occupied when unknown_is_occupied (the
/// planner's conservative default) and free otherwise. nullopt with *error naming the field
/// for a delta, bad dims or resolution, a size mismatch or a value outside the constants.
std::optional<OccupancyGrid<3>> FromFullMapMessage(const map_update_t& msg,
                                                   bool unknown_is_occupied, std::string* error);

/// Applies a delta (is_full false) to *grid, which must have the message's geometry. False
/// with *error (grid unchanged) for a full message, another geometry or an index out of range.
bool ApplyMapDelta(const map_update_t& msg, bool unknown_is_occupied, OccupancyGrid<3>* grid,
                   std::string* error);

}  // namespace topay::msgs
