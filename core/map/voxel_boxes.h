#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/map/cell_box.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid3.h"

namespace topay {

/// Few axis-aligned boxes of voxels covering exactly the voxels i with cells[i] == value (and
/// no other), pairwise disjoint. `cells` is a grid of `dims` voxels in GridGeometry3's order
/// (x fastest). Greedy, in one pass over the voxels: maximal runs along x in each row; in each
/// layer, a run continues the rectangle above it (previous row) with the same x extent; each
/// layer's rectangles continue the box below (previous layer) with the same xy extent. Not
/// the fewest boxes (that problem is NP-hard), but a wall or table top gives one box per
/// distinct cross-section. Throws std::invalid_argument if cells.size() != dims' product.
/// Cost: O(voxels + rectangles log rectangles).
std::vector<CellBox> MergeVoxelsIntoBoxes(const Eigen::Vector3i& dims,
                                          std::span<const std::uint8_t> cells, std::uint8_t value);

/// The world box (yaw 0) covered by a box of voxels of `geometry`.
OrientedBox VoxelBoxInWorld(const GridGeometry3& geometry, const CellBox& voxels);

/// The occupied voxels of a grid as world boxes (MergeVoxelsIntoBoxes), e.g. for validating a
/// plan against a sensed map's voxels.
std::vector<OrientedBox> OccupiedVoxelBoxes(const OccupancyGrid3& grid);

/// The voxels in state VoxelState::kOccupied of a state array (OccupancyMap::states(),
/// geometry's order) as world boxes. Throws std::invalid_argument for a size mismatch.
std::vector<OrientedBox> OccupiedVoxelBoxes(const GridGeometry3& geometry,
                                            std::span<const std::uint8_t> states);

}  // namespace topay
