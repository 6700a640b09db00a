#pragma once

// Shared by the mapper's tests: simulated scans as checked clouds, robot states clear of a
// scene.

#include <cstdint>
#include <vector>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/robot/kinematics.h"
#include "procs/msgs/cloud_input.h"
#include "sim/lidar/lidar_scanner.h"

namespace topay::mapper::testing {

/// The points of `scan` whose target `keep` accepts, as a checked cloud at the scan's pose.
template <typename Keep>
msgs::CheckedCloud CloudOf(const sim::LidarScan& scan, Keep keep) {
  msgs::CheckedCloud cloud;
  cloud.utime = static_cast<std::int64_t>(scan.t_s * 1e6);
  cloud.X_WS = scan.X_WS;
  for (std::size_t k = 0; k < scan.p_SP.size(); ++k) {
    if (keep(scan.target[k])) cloud.p_SP.push_back(scan.p_SP[k]);
  }
  return cloud;
}

inline msgs::CheckedCloud CloudOf(const sim::LidarScan& scan) {
  return CloudOf(scan, [](std::int32_t) { return true; });
}

/// A seeded state with the whole body (base and arm) more than `clearance_m` from every box
/// of `scene`, the base in
/// [-8, 8]^2 m, and the arm at `q` or, if q is empty, uniform within the joint limits.
inline WholeBodyState ClearState(const Kinematics& kinematics, const Scene& scene,
                                 double clearance_m, Rng* rng, const Eigen::VectorXd& q = {}) {
  const RobotModel& model = kinematics.model();
  const SceneClearanceChecker checker(kinematics, scene);
  while (true) {
    WholeBodyState state;
    state.x_m = rng->Uniform(-8, 8);
    state.y_m = rng->Uniform(-8, 8);
    state.yaw_rad = rng->Uniform(-3.14159, 3.14159);
    state.q_rad = q;
    if (q.size() == 0) {
      state.q_rad.resize(model.num_joints());
      for (int i = 0; i < model.num_joints(); ++i) {
        state.q_rad(i) =
            rng->Uniform(model.joint_limits.q_min_rad(i), model.joint_limits.q_max_rad(i));
      }
    }
    if (checker.BaseClearance({state.x_m, state.y_m}, 1.0) > clearance_m &&
        checker.Compute(state).obstacle_m() > clearance_m) {
      return state;
    }
  }
}

}  // namespace topay::mapper::testing
