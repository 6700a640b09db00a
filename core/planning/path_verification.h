#pragma once

#include <string>

#include <Eigen/Geometry>

#include "core/collision/scene_clearance.h"
#include "core/planning/discrete_se2.h"
#include "core/planning/whole_body_path.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Options of VerifyWholeBodyPath: the acceptance test of a front-end path (exact clearance along states at most 0.01 m / 0.01 rad apart).
struct PathVerificationOptions {
  /// Interpolation between consecutive states (linear in x, y, yaw, q): consecutive checked
  /// states differ by at most this in base position and in yaw and every joint.
  double max_step_m = 0.01;
  double max_step_rad = 0.01;
  /// Exact clearances required (SceneClearance::IsCollisionFree).
  double obstacle_margin_m = 0.0;
  double self_margin_m = 0.0;
  /// End effector at the last state vs the target.
  double position_tolerance_m = 1e-3;
  double orientation_tolerance_rad = 1e-2;
  /// The first state must equal the start within this (m, rad; yaw compared modulo 2 pi).
  double start_tolerance = 1e-9;
};

struct PathVerification {
  bool ok = false;
  std::string message;  ///< Empty if ok, else the first failure and where.
  int num_states_checked = 0;  ///< Interpolated states checked exactly.
  double min_obstacle_clearance_m = SceneClearance::kInfinity;
};

/// Independent check of a whole-body path against the exact scene geometry (no distance
/// field): times and states sized alike, times increasing, the first state the start, joint
/// limits, every interpolated state exactly collision free (base, arm, self, chassis), the
/// end effector of the last state at X_WE_target, and, if `layers` is given, each state on
/// a layer of it with consecutive states on the same or adjacent layers, first on the first
/// and last on the last.
PathVerification VerifyWholeBodyPath(const WholeBodyPath& path, const WholeBodyState& start,
                                     const Eigen::Isometry3d& X_WE_target,
                                     const SceneClearanceChecker& checker,
                                     const Kinematics& kinematics,
                                     const DiscreteSE2Path* layers = nullptr,
                                     const PathVerificationOptions& options = {});

}  // namespace topay
