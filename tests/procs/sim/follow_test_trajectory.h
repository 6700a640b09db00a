#pragma once
// A real trajectory for the follower's tests: MINCO s = 3 solved by ArcYawTrajectory::Update
// from rest at (p0, yaw0, q0) to rest 1 m of arc ahead, turned by turn_rad, every joint moved by
// joint_change_rad, through one waypoint (2 pieces of 1 s), as TRAJECTORY carries it.

#include <cstdint>

#include <Eigen/Core>

#include "core/trajectory/arc_yaw_trajectory.h"
#include "procs/msgs/convert_trajectory.h"
#include "topay/poly_trajectory_t.hpp"

namespace topay::test {

inline ArcYawTrajectory FollowTestTrajectory(const Eigen::Vector2d& p0_W_m, double yaw0_rad,
                                             const Eigen::VectorXd& q0_rad, double turn_rad = 0.5,
                                             double joint_change_rad = 0.3) {
  const int n = static_cast<int>(q0_rad.size());
  ArcYawTrajectory trajectory(n, 2, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(n + 2, 3), tail = Eigen::MatrixXd::Zero(n + 2, 3);
  head(1, 0) = yaw0_rad;
  head.col(0).tail(n) = q0_rad;
  tail(0, 0) = 1.0;
  tail(1, 0) = yaw0_rad + turn_rad;
  tail.col(0).tail(n) = q0_rad.array() + joint_change_rad;
  const Eigen::MatrixXd waypoints = 0.5 * (head.col(0) + tail.col(0));
  trajectory.Update(p0_W_m, head, tail, waypoints, Eigen::Vector2d(1.0, 1.0));
  return trajectory;
}

inline poly_trajectory_t FollowTestMessage(const ArcYawTrajectory& trajectory, const Eigen::Vector2d& p0_W_m,
                                           std::int64_t start_utime, std::int64_t id) {
  msgs::PolyTrajectory poly = msgs::FromArcYaw(trajectory, p0_W_m);
  poly.utime = start_utime;
  poly.start_utime = start_utime;
  poly.trajectory_id = id;
  poly.goal_id = 1;
  return msgs::ToMessage(poly);
}

}  // namespace topay::test
