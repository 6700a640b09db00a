#pragma once
// The figures of one sensed map (topay-bench --sensed-map), kept in the task's records.

#include <cstdint>

#include "core/map/occupancy_map.h"

namespace topay::bench {

/// What building one sensed map took and gave.
struct SensedMapFigures {
  int scans = 0;                      ///< Tour poses scanned.
  std::int64_t points = 0;            ///< LiDAR points returned, all scans.
  std::int64_t points_mapped = 0;     ///< ... left by the scan filter.
  std::int64_t self_points = 0;       ///< Points on the robot (all removed, or counted here).
  VoxelStateCounts voxels;            ///< The map's voxel states at the end.
  int voxel_boxes = 0;                ///< Boxes of blocked voxels the planner validates on.
  double lidar_ms = 0.0;              ///< Simulated scanning (not the mapper's cost).
  double mapping_ms = 0.0;            ///< Scan filter + insertion, all scans.
  double fields_ms = 0.0;             ///< VoxelMapFields from the changes.
  double boxes_ms = 0.0;              ///< The voxel boxes.
};

}  // namespace topay::bench
