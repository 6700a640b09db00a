#pragma once
// A trajectory moved to where the robot is: the same motion from another start pose and
// configuration (the planner's safe stop for a robot off its trajectory, finding 34).

#include <Eigen/Core>

#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay {

/// `trajectory` started at p0_W (m, in W) instead of its own start, with yaw_offset_rad added
/// to its yaw and q_offset_rad (size N) to its joints at every time; s and every rate and
/// acceleration unchanged. Its base path is the original's turned by yaw_offset_rad about the
/// start and moved to p0_W (paper eqs. (1)-(2) integrate s'(cos yaw, sin yaw) of the turned
/// yaw). Made by solving MINCO again (paper Sec. III-B) with the original's durations, its
/// boundary conditions (15)-(20) and interior waypoints sampled from it, the offsets added to
/// their positions: a constant added to a dimension's boundary and waypoint positions adds it
/// to each of its pieces' c0 and changes nothing else, so the result is the original motion
/// (to rounding) moved. Allocates. Throws std::invalid_argument for a non-finite offset, a
/// q_offset of the wrong size or a trajectory never updated.
ArcYawTrajectory OffsetTrajectory(const ArcYawTrajectory& trajectory, const Eigen::Vector2d& p0_W, double yaw_offset_rad,
                                  const Eigen::VectorXd& q_offset_rad, const ArcYawTrajectory::Options& options = {});

}  // namespace topay
