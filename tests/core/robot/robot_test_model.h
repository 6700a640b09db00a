#pragma once

// Shared by the core/robot tests: the project's robot model and random whole-body states.

#include <string>

#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"

namespace topay::testing {

inline RobotModel LoadTopayModel() {
  const std::string dir = std::string(TOPAY_SOURCE_DIR) + "/config/robot/";
  return LoadRobotModel(dir + "topay_mm.urdf", dir + "topay_mm.yaml");
}

/// A state with the base uniform in [-5, 5]^2 m x (-pi, pi] and q uniform within the limits.
inline WholeBodyState RandomState(const RobotModel& model, Rng* rng) {
  WholeBodyState state;
  state.x_m = rng->Uniform(-5.0, 5.0);
  state.y_m = rng->Uniform(-5.0, 5.0);
  state.yaw_rad = rng->Uniform(-3.14159, 3.14159);
  state.q_rad.resize(model.num_joints());
  for (int i = 0; i < model.num_joints(); ++i) {
    state.q_rad(i) = rng->Uniform(model.joint_limits.q_min_rad(i), model.joint_limits.q_max_rad(i));
  }
  return state;
}

}  // namespace topay::testing
