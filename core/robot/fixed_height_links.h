#pragma once

#include <vector>

#include "core/robot/robot_model.h"

namespace topay {

/// For each link of `model` (model order): true when the link frame keeps its height above the
/// base frame and its z axis vertical (up or down) for every joint configuration, so every
/// point rigidly attached to it (a collision sphere) stays at one height. The root (the base
/// frame) qualifies; a link qualifies when its parent does, its joint frame's z axis is
/// vertical in the parent (X_PJ maps e_z to +-e_z) and its joint is fixed or revolute about
/// that vertical axis (axis_J = +-e_z). Prismatic joints never qualify (conservative). On the
/// TopAY arm only link1 (the shoulder's yaw joint) qualifies.
///
/// Used to leave such spheres out of state-dependent clearance penalties whose value they
/// cannot change (the arm-above-chassis margin: SamplePenalties).
std::vector<bool> FixedHeightLinks(const RobotModel& model);

}  // namespace topay
