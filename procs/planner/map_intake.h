#pragma once
// The planner's side of MAP_UPDATE on the LCM thread: the receiver's copy of the mapper's grid
// (msgs::MapReceiver), turned into work for the planning thread's distance fields (MapWork:
// the voxels that changed, or a whole new grid), and the blocked voxels near a region as
// boxes for the check of the trajectory ahead. Cheap per message (decode and copy), so the
// LCM loop stays responsive; the fields are updated on the planning thread in batches.

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/oriented_box.h"
#include "core/map/grid_geometry.h"
#include "core/robot/kinematics.h"
#include "core/map/voxel_map_fields.h"
#include "core/robot/robot_model.h"
#include "procs/msgs/map_receiver.h"
#include "procs/planner/standing_robot.h"
#include "topay/map_update_t.hpp"

namespace topay::planner {

/// What the planning thread must do to its fields to follow the map.
struct MapWork {
  /// True: a new grid (first map, or another geometry): rebuild from `states`. False: apply
  /// `changes` in order.
  bool reset = false;
  GridGeometry3 geometry;
  std::vector<std::uint8_t> states;   ///< reset only: every voxel (GridGeometry3 order)
  std::vector<VoxelChange> changes;   ///< !reset: the voxels that changed
  std::int64_t map_seq = 0;           ///< the map's sequence number after this work
  std::int64_t map_utime = 0;         ///< its time, us since the Unix epoch
};

class MapIntake {
 public:
  MapIntake(UnknownVoxelPolicy unknown, const msgs::MapCodecOptions& codec = {});

  /// Decodes and applies `msg` (MapReceiver::Accept, returned in *result). A delta gives its
  /// changes; a snapshot of the grid already held gives the voxels that differ (nullopt if
  /// none), of a new geometry a reset; a rejected or out-of-order message nothing.
  std::optional<MapWork> Accept(const map_update_t& msg, msgs::MapAcceptResult* result);

  const msgs::MapReceiver& receiver() const { return receiver_; }
  bool has_map() const { return receiver_.has_map(); }

  /// The voxels the planner counts as obstacles (VoxelBlocksPlanner) that overlap
  /// `region_W_m`, merged into world boxes. Empty before the first map.
  std::vector<OrientedBox> BlockedBoxesNear(const Eigen::AlignedBox3d& region_W_m) const;
  /// As above, but without the voxels `standing` leaves out (ClearStandingRobot): the map as
  /// a plan from rest at standing.state was validated on. Copies the grid's states (one byte a
  /// voxel) when the region meets the standing robot (StandingRobotBounds).
  std::vector<OrientedBox> BlockedBoxesNear(const Eigen::AlignedBox3d& region_W_m, const Kinematics& kinematics,
                                            const StandingRobot& standing) const;
  /// True if p_W lies in a blocked voxel or within `clearance_m` of one.
  bool NearBlocked(const Eigen::Vector3d& p_W, double clearance_m) const;

 private:
  UnknownVoxelPolicy unknown_;
  msgs::MapReceiver receiver_;
  std::vector<std::uint8_t> forwarded_;  // what the planning thread will hold after our work
  GridGeometry3 forwarded_geometry_;
};

/// Sets free every blocked voxel (VoxelBlocksPlanner) that reaches into the base cylinder
/// standing at p_WB (its square nearer the axis than the radius, its bottom below the top):
/// the robot stands there, so what the map holds inside its own base is its own body seen by
/// the LiDAR, a stale voxel, or the conservative voxel of an obstacle touching the base's
/// surface within a voxel (a plan from where the robot is must not fail on it; costmaps clear
/// the footprint the same way). Only the exact check loses them: the fields keep them, so the
/// optimizer still keeps its margins from them. Returns the voxels cleared.
int ClearBaseFootprint(const GridGeometry3& geometry, const Eigen::Vector2d& p_WB_m,
                       const BaseCylinder& base, UnknownVoxelPolicy unknown,
                       std::vector<std::uint8_t>* states);

/// Sets free every blocked voxel that a collision sphere of the robot standing at `state`
/// reaches into by at most max_depth_m (the distance from the sphere's centre to the voxel's
/// box is less than its radius, and more than radius - max_depth_m): as for the base, the
/// robot stands there, and a shallow overlap is the sensed map standing out of a surface the
/// arm is near (a safe stop beside a table left an arm sphere 2 mm "inside" a voxel, and every
/// plan from rest failed on its start). Deeper overlaps stay: the map's word that the arm is
/// in something. Only the exact check loses them (the fields keep them). Returns the voxels
/// cleared.
int ClearArmOverlaps(const GridGeometry3& geometry, const Kinematics& kinematics, const WholeBodyState& state,
                     double max_depth_m, UnknownVoxelPolicy unknown, std::vector<std::uint8_t>* states);

}  // namespace topay::planner
