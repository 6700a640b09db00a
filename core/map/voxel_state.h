#pragma once

#include <cstdint>

#include <Eigen/Core>

namespace topay {

/// What the map knows of one voxel (one byte each).
enum class VoxelState : std::uint8_t {
  kFree = 0,      ///< Seen free (a ray passed through it).
  kOccupied = 1,  ///< Seen occupied (a return in it).
  kUnknown = 2,   ///< Never observed (or forgotten).
};

/// One voxel's new state, by index (ix, iy, iz) into the map's GridGeometry3 (e.g.
/// VoxelMapFields::geometry(), OccupancyMap::geometry()).
struct VoxelChange {
  Eigen::Vector3i voxel = Eigen::Vector3i::Zero();
  VoxelState state = VoxelState::kOccupied;
};

}  // namespace topay
