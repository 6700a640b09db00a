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

Eigen::AlignedBox3d StandingRobotBounds(const Kinematics& kinematics, const StandingRobot& standing,
                                        double resolution_m) {
  const BaseCylinder& base = kinematics.model().base_cylinder;
  const Eigen::Vector3d p_WB(standing.state.x_m, standing.state.y_m, 0.0);
  Eigen::AlignedBox3d bounds(p_WB - Eigen::Vector3d(base.radius_m, base.radius_m, 0.0),
                             p_WB + Eigen::Vector3d(base.radius_m, base.radius_m, base.height_m));
  KinematicsCache cache = kinematics.MakeCache();
  kinematics.Update(standing.state, &cache);
  for (std::size_t s = 0; s < cache.p_WS.size(); ++s) {
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(kinematics.model().spheres[s].radius_m);
    bounds.extend(cache.p_WS[s] - r);
    bounds.extend(cache.p_WS[s] + r);
  }
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(resolution_m);
  return {bounds.min() - grow, bounds.max() + grow};
}

}  // namespace topay::planner
