#include "procs/planner/standing_robot.h"

#include "procs/planner/map_intake.h"

namespace topay::planner {

int ClearStandingRobot(const GridGeometry3& geometry, const Kinematics& kinematics, const StandingRobot& standing,
                       UnknownVoxelPolicy unknown, std::vector<std::uint8_t>* states) {
  int cleared = ClearBaseFootprint(geometry, {standing.state.x_m, standing.state.y_m},
                                   kinematics.model().base_cylinder, unknown, states);
  if (standing.arm_overlap_m > 0.0) {
    cleared += ClearArmOverlaps(geometry, kinematics, standing.state, standing.arm_overlap_m, unknown, states);
  }
  return cleared;
}

}  // namespace topay::planner
