#pragma once
// Shared by the planner process's tests: maps of voxel states made from boxes (every voxel a
// box overlaps is occupied, the rest free), a small room, and the robot.

#include <cstdint>
#include <vector>

#include "core/geometry/scene.h"
#include "core/map/grid_geometry.h"
#include "core/map/voxel_boxes.h"
#include "core/map/voxel_state.h"
#include "tests/common/make_box.h"

namespace topay::planner::testing {

/// Every voxel of `geometry` free, but those the (upright, unrotated) boxes overlap: occupied.
inline std::vector<std::uint8_t> StatesOf(const GridGeometry3& geometry, const std::vector<OrientedBox>& boxes) {
  std::vector<std::uint8_t> states(static_cast<std::size_t>(geometry.NumCells()),
                                   static_cast<std::uint8_t>(VoxelState::kFree));
  for (const OrientedBox& b : boxes) {
    const Eigen::Vector3d half = 0.5 * b.size_m;
    const CellBox cells = VoxelsOverlapping(geometry, {b.center_W_m - half, b.center_W_m + half});
    for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz) {
      for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy) {
        for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) {
          states[geometry.Index(ix, iy, iz)] = static_cast<std::uint8_t>(VoxelState::kOccupied);
        }
      }
    }
  }
  return states;
}

/// A body the LiDAR saw only from outside, as changes to a map: of the voxels the (upright,
/// unrotated) box overlaps, those on the rim of each layer occupied, the inside unknown.
inline std::vector<VoxelChange> UnseenBody(const GridGeometry3& geometry, const OrientedBox& box) {
  const Eigen::Vector3d half = 0.5 * box.size_m;
  const CellBox cells = VoxelsOverlapping(geometry, {box.center_W_m - half, box.center_W_m + half});
  std::vector<VoxelChange> changes;
  for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz) {
    for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy) {
      for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) {
        const bool rim = ix == cells.begin.x() || iy == cells.begin.y() || ix + 1 == cells.end.x() ||
                         iy + 1 == cells.end.y();
        changes.push_back({{ix, iy, iz}, rim ? VoxelState::kOccupied : VoxelState::kUnknown});
      }
    }
  }
  return changes;
}

/// An 8 x 8 m room (walls 0.1 m thick, 1.2 m high) with a table-like box in the middle, z
/// up to 1.6 m, at 5 cm voxels.
inline GridGeometry3 RoomGeometry() {
  return GridGeometry3::FromBounds({Eigen::Vector3d(-4.0, -4.0, 0.0), Eigen::Vector3d(4.0, 4.0, 1.6)}, 0.05);
}

inline std::vector<OrientedBox> RoomBoxes() {
  return {MakeBox({0.0, 3.9, 0.6}, {8.0, 0.2, 1.2}), MakeBox({0.0, -3.9, 0.6}, {8.0, 0.2, 1.2}),
          MakeBox({3.9, 0.0, 0.6}, {0.2, 8.0, 1.2}), MakeBox({-3.9, 0.0, 0.6}, {0.2, 8.0, 1.2}),
          MakeBox({0.0, 0.0, 0.375}, {1.0, 1.0, 0.75})};
}

}  // namespace topay::planner::testing
