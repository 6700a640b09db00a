#pragma once
// Trajectories for the tracker's tests: MINCO s = 3 solved by ArcYawTrajectory::Update from
// rest at (p0, yaw0, q0) to rest `arc_m` of arc ahead, turned by turn_rad, every joint moved by
// joint_change_rad (one value per joint, or empty: 0.3 rad each), through one waypoint (2
// pieces of piece_s), and the TRAJECTORY message
// carrying it. The defaults (1 m, 0.5 rad, 0.3 rad over 4 s) stay well within the robot's
// limits, the coupled v-omega bound included (peak |v| / v_max + |omega| / omega_max < 0.75).

#include <cstdint>

#include <Eigen/Core>

#include "core/trajectory/arc_yaw_trajectory.h"
#include "procs/msgs/convert_trajectory.h"
#include "topay/poly_trajectory_t.hpp"

namespace topay::test {

inline ArcYawTrajectory TrackerTestTrajectory(const Eigen::Vector2d& p0_W_m, double yaw0_rad,
                                              const Eigen::VectorXd& q0_rad, double arc_m = 1.0,
                                              double turn_rad = 0.5, Eigen::VectorXd joint_change_rad = {},
                                              double piece_s = 2.0) {
  const int n = static_cast<int>(q0_rad.size());
  if (joint_change_rad.size() == 0) joint_change_rad = Eigen::VectorXd::Constant(n, 0.3);
  ArcYawTrajectory trajectory(n, 2, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(n + 2, 3), tail = Eigen::MatrixXd::Zero(n + 2, 3);
  head(1, 0) = yaw0_rad;
  head.col(0).tail(n) = q0_rad;
  tail(0, 0) = arc_m;
  tail(1, 0) = yaw0_rad + turn_rad;
  tail.col(0).tail(n) = q0_rad + joint_change_rad;
  const Eigen::MatrixXd waypoints = 0.5 * (head.col(0) + tail.col(0));
  trajectory.Update(p0_W_m, head, tail, waypoints, Eigen::Vector2d(piece_s, piece_s));
  return trajectory;
}

inline poly_trajectory_t TrackerTestMessage(const ArcYawTrajectory& trajectory, const Eigen::Vector2d& p0_W_m,
                                            std::int64_t start_utime, std::int64_t id, std::int64_t goal_id = 1) {
  msgs::PolyTrajectory poly = msgs::FromArcYaw(trajectory, p0_W_m);
  poly.utime = start_utime;
  poly.start_utime = start_utime;
  poly.trajectory_id = id;
  poly.goal_id = goal_id;
  return msgs::ToMessage(poly);
}

}  // namespace topay::test
