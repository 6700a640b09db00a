#pragma once
// Messages for the estimator's node and process tests.

#include <cstdint>
#include <string>

#include "topay/base_pose_t.hpp"
#include "topay/base_velocity_t.hpp"
#include "topay/joint_state_t.hpp"

namespace topay::test {

inline base_pose_t PoseMessage(std::int64_t utime, double x_m, double y_m, double yaw_rad) {
  base_pose_t m;
  m.utime = utime;
  m.x_m = x_m;
  m.y_m = y_m;
  m.yaw_rad = yaw_rad;
  return m;
}

inline base_velocity_t VelocityMessage(std::int64_t utime, double v_mps, double omega_radps) {
  base_velocity_t m;
  m.utime = utime;
  m.v_mps = v_mps;
  m.omega_radps = omega_radps;
  return m;
}

/// 7 arm joints at q_j = base + 0.1 j, rates 0.01 j.
inline joint_state_t JointMessage(std::int64_t utime, double base_rad = 0.0, int n = 7) {
  joint_state_t m;
  m.utime = utime;
  m.num_joints = n;
  for (int j = 0; j < n; ++j) {
    m.names.push_back("joint" + std::to_string(j + 1));
    m.position_rad.push_back(base_rad + 0.1 * j);
    m.velocity_radps.push_back(0.01 * j);
    m.effort_Nm.push_back(0.5 * j);
  }
  return m;
}

inline joint_state_t GripperMessage(std::int64_t utime, double position) {
  joint_state_t m;
  m.utime = utime;
  m.num_joints = 1;
  m.names = {"gripper"};
  m.position_rad = {position};
  m.velocity_radps = {0.0};
  m.effort_Nm = {0.0};
  return m;
}

}  // namespace topay::test
