#pragma once

#include <memory>
#include <span>
#include <vector>

#include <octomap/OcTree.h>

#include "core/map/grid_geometry.h"
#include "core/map/voxel_map_fields.h"
#include "procs/mapper/octomap_mirror.h"

namespace topay::mapper {

/// Per-voxel states of `tree` over the dense grid `grid` (indexed by grid.Index, x fastest),
/// so the dense map (VoxelMapFields) can start from a prior (`--prior map.bt`): a voxel whose
/// centre lies in a known leaf of the tree is kOccupied or kFree as the leaf is
/// (OcTree::isNodeOccupied), every other voxel kUnknown. Pruned leaves (larger than one
/// voxel) fill every voxel they cover; the tree may have another resolution than the grid.
/// Cost: one pass over the tree's leaves in the grid's bounds plus one over the grid.
std::vector<VoxelState> DenseStatesFromOcTree(const octomap::OcTree& tree,
                                              const GridGeometry3& grid);

/// The inverse, so a .bt can be written from the dense map itself (e.g. when the mirror lags
/// behind it): a tree at grid.resolution_m with `options`' sensor model where each kOccupied
/// voxel is a leaf at the upper clamping bound and each kFree one at the lower bound
/// (kUnknown: no node), pruned. `states` must have grid.NumCells() entries
/// (std::invalid_argument otherwise). The grid's cells should be aligned with the tree's
/// voxels (origin a multiple of the resolution, as the default map's) for an exact round trip.
std::unique_ptr<octomap::OcTree> OcTreeFromDenseStates(std::span<const VoxelState> states,
                                                       const GridGeometry3& grid,
                                                       const OctomapMirrorOptions& options);

}  // namespace topay::mapper
