#pragma once
// Is a point inside an obstacle whose inside the sensor never saw? A LiDAR sees only the
// surfaces of a solid box: its inside stays unknown, and a planner that counts unknown voxels
// as free (UnknownVoxelPolicy::kFree) would take a target at the box's centre (fault campaign
// finding 35, docs/reliability.md). FindUnseenPocket answers from the map alone: the target's
// voxel was never observed, the unknown voxels 4-connected to it within its layer (its pocket)
// stay near it, and the pocket's rim (the seen voxels around it) is mostly occupied: a body
// seen from around, not the gap between two rays in seen-free space.
//
// Why a rim and not a closed wall: in a map from a noisy LiDAR (2 cm) a box's side is a band
// of occupied and free voxels (rays grazing it, returns falling short and long), seldom a
// closed line of occupied ones, while its inside, where no ray goes, stays unknown in one
// piece (tests/core/map/unseen_pocket_scene_test.cc has a picture of such a layer).
// Why one layer: a LiDAR below a box's top (the robot's, at 0.22 m) never sees the top, so a
// 3D pocket would spill out through it; and the layer under a table top's unseen upper side is
// the top itself. A side not seen yet (the pocket runs on into the box's shadow), a pocket
// wider than max_reach_m and a target in a voxel seen free all give "not enclosed": the check
// refuses only what the map shows closed.

#include <cstdint>
#include <span>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/map/grid_geometry.h"

namespace topay {

struct UnseenPocketOptions {
  /// The pocket may reach this far (m) from the target along x and y: one that reaches farther
  /// (a room's unseen corner, the shadow behind a wall) is not enclosed. > 0.
  double max_reach_m = 1.0;
  /// The share of the pocket's rim that must be occupied, in [0, 1] (a gap between rays in the
  /// open: 0). At 0.5, in a map of a benchmark room scanned from 40 poses
  /// (tests/core/map/unseen_pocket_scene_test.cc), 83 of 160 box centres are enclosed, and 16
  /// of 40,000 points clear of every box (none of them 0.2 m clear: nooks between boxes).
  double min_occupied_rim_share = 0.5;
};

/// What the fill found.
struct UnseenPocket {
  /// The target's voxel is unknown, its pocket stays within reach and its rim is occupied enough.
  bool enclosed = false;
  int voxels = 0;        ///< voxels of the pocket filled (all of it when enclosed)
  int rim_occupied = 0;  ///< its rim's occupied voxels ...
  int rim_free = 0;      ///< ... and free ones
  /// The pocket's voxels' extent in x and y (m, W); empty when no voxel was filled.
  Eigen::AlignedBox2d extent_W_m;
  /// Why it is not enclosed ("" when it is): the target's voxel seen free or occupied, outside
  /// the grid, the pocket reaching the grid's edge or beyond max_reach_m, or its rim mostly free.
  std::string open_because;
};

/// The unseen pocket of the voxel holding p_W in `states` (one VoxelState byte per voxel of
/// `grid`, GridGeometry3::Index order, as OccupancyMap::states() and the planner's map
/// receiver hold them). Throws std::invalid_argument if states does not match the grid, p_W
/// is not finite or an option is out of its range. Cost: at most
/// (2 max_reach_m / resolution + 1)^2 voxels visited (1,681 at 1 m and 5 cm); allocates its window and stack.
UnseenPocket FindUnseenPocket(const GridGeometry3& grid, std::span<const std::uint8_t> states,
                              const Eigen::Vector3d& p_W, const UnseenPocketOptions& options = {});

}  // namespace topay
