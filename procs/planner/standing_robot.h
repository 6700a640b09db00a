#pragma once
// The robot standing still where a plan from rest starts, and the voxels of the map that plan
// is checked without: those its base reaches into, and those its arm spheres reach into by at
// most arm_overlap_m (ClearBaseFootprint, ClearArmOverlaps in map_intake.h: its own body seen
// by the LiDAR, or the sensed map standing out of a surface it stopped near). The planning
// thread validates the plan on that map; the planner's checks against newer maps (the plan as
// it comes, the trajectory while it runs, a stop braking from it) leave the same voxels out.
// Before, a robot stopped with link7 9 mm in freshly sensed voxels had every plan from rest
// validated, then refused as "colliding with the newer map at 0.00 s" (a PlannerGraph test
// stuck for 60 s).

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "core/map/grid_geometry.h"
#include "core/map/voxel_map_fields.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"

namespace topay::planner {

struct StandingRobot {
  WholeBodyState state;          ///< where the robot stands (a plan from rest starts there)
  double arm_overlap_m = 0.0;    ///< arm overlaps up to this deep (m) are its own; >= 0
};

/// Sets free the voxels of `states` (geometry's grid) that `standing` leaves out of the check:
/// ClearBaseFootprint at its base, then ClearArmOverlaps with its arm_overlap_m (when > 0).
/// Returns the voxels cleared.
int ClearStandingRobot(const GridGeometry3& geometry, const Kinematics& kinematics, const StandingRobot& standing,
                       UnknownVoxelPolicy unknown, std::vector<std::uint8_t>* states);

/// A world box holding every voxel ClearStandingRobot may clear: the base cylinder and the arm's
/// collision spheres of the standing robot, grown by one voxel (`resolution_m`).
Eigen::AlignedBox3d StandingRobotBounds(const Kinematics& kinematics, const StandingRobot& standing,
                                        double resolution_m);

}  // namespace topay::planner
