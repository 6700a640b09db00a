#pragma once

#include <string>

#include <Eigen/Geometry>

#include "core/map/signed_distance_field3.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_rates.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// The problem's inputs besides the fields and the robot (paper Sec. III-C).
struct TrajectoryProblem {
  WholeBodyState start;           ///< s(0) = 0.
  /// The start's rates (v, omega, a, beta, qd, qdd): the trajectory's head velocity and
  /// acceleration columns, so that it joins a motion under way C2-continuously (issue 18).
  /// Default: at rest (conditions (15)-(17) of the paper). The flatness baseline refuses a
  /// start that is not at rest.
  WholeBodyRates start_rates;
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();  ///< p_e of eq. (7).
  BaseLimits base_limits;         ///< Caller-chosen (the benchmark: omega_max 1.25).
  /// Leading and trailing states of the front-end path that were validated exactly rather than
  /// on the fields (the start or the goal lies inside the fields' margins; core/planning).
  /// The back end relaxes its clearance margins there (EndpointRelief). 0: none (default).
  int exact_prefix_states = 0;
  int exact_suffix_states = 0;
};

/// The heights (m, world z) the end-effector frame's origin can reach: joint 1's height -+
/// the chain's length bound from joint 1 to E (the first movable joint of E's chain stays at
/// a fixed height over the base; from it, E is at most the sum of the chain's fixed offsets
/// away: triangle inequality).
struct ReachHeights {
  double min_z_m = 0.0;
  double max_z_m = 0.0;
};
ReachHeights ComputeReachHeights(const Kinematics& kinematics);

/// What every back end checks before it starts: the start state (joint count, finite, joints
/// within limits), its rates (finite, joint vectors empty or of the robot's joint count), the base limits (finite, > 0), the goal pose (finite, orthonormal), its
/// height within `reach` and the target not clearly inside an obstacle on the 3D field
/// (negative by more than a cell). Returns the reason the inputs are unusable, or "".
std::string CheckTrajectoryProblem(const TrajectoryProblem& problem, const Kinematics& kinematics,
                                   const SignedDistanceField3& arm_field,
                                   const ReachHeights& reach);

/// The problem's exact_prefix_states and exact_suffix_states against the path they count
/// states of: each in [0, path size]. Returns the reason they are unusable, or "".
std::string CheckExactPathStretches(const TrajectoryProblem& problem, int path_size);

}  // namespace topay
