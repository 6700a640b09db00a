#pragma once
// A small arc length-yaw trajectory for tests: 4 m along +x in 8 s from (1, 2), rest to rest,
// its 2 joints from 0 to 0.4 rad.

#include <memory>

#include <Eigen/Core>

#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay::test {

inline std::shared_ptr<ArcYawTrajectory> StraightDrive() {
  auto t = std::make_shared<ArcYawTrajectory>(2, 4, ArcYawTrajectory::Options{});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(4, 3), tail = Eigen::MatrixXd::Zero(4, 3);
  tail(0, 0) = 4.0;
  tail(2, 0) = tail(3, 0) = 0.4;
  Eigen::MatrixXd waypoints(4, 3);
  waypoints << 0.5, 2.0, 3.5, 0, 0, 0, 0.05, 0.2, 0.35, 0.05, 0.2, 0.35;
  t->Update({1.0, 2.0}, head, tail, waypoints, Eigen::VectorXd::Constant(4, 2.0));
  return t;
}

}  // namespace topay::test
