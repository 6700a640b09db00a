#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/map/cell_box.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid3.h"
#include "core/map/voxel_map_fields.h"

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

/// True if a voxel in `state` is an obstacle to the planner's exact checks (its validator and
/// the checks of a trajectory against the map) under `unknown`: occupied voxels always,
/// unknown ones unless the policy counts them as free (kFree) or blocks them only for the
/// base's 2D field (kOccupiedInBaseBands: the exact checks, which cannot tell base from arm
/// per voxel, take them as free, as the arm's 3D field does).
bool VoxelBlocksPlanner(VoxelState state, UnknownVoxelPolicy unknown);

/// The planner's obstacles in the voxels of `region` (clipped to the grid; whole grid by
/// default) as world boxes: VoxelBlocksPlanner voxels merged by MergeVoxelsIntoBoxes over the
/// region's sub-grid. Cost: the region's voxels. Throws std::invalid_argument for a size
/// mismatch of `states`.
std::vector<OrientedBox> BlockedVoxelBoxes(const GridGeometry3& geometry,
                                           std::span<const std::uint8_t> states,
                                           UnknownVoxelPolicy unknown, CellBox region);
std::vector<OrientedBox> BlockedVoxelBoxes(const GridGeometry3& geometry,
                                           std::span<const std::uint8_t> states,
                                           UnknownVoxelPolicy unknown);

/// The voxels of `geometry` whose interior the world box `box_W_m` meets (a box face lying on
/// a voxel face takes no voxel beyond it; a flat box the voxels it lies in), clipped to the
/// grid (empty if none).
CellBox VoxelsOverlapping(const GridGeometry3& geometry, const Eigen::AlignedBox3d& box_W_m);

}  // namespace topay
