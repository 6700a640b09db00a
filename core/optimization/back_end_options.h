#pragma once

#include <string_view>

#include "core/optimization/augmented_lagrangian.h"
#include "core/optimization/lbfgs_solve.h"
#include "core/optimization/warm_start.h"

namespace topay {

/// The options every trajectory back end takes (TrajectoryBackEnd: the arc length-yaw
/// TrajectoryOptimizer and the flatness baseline FlatnessOptimizer), Ceres style; each
/// back end's options struct derives from it and adds its own. Defaults: the authors' code's
/// "Trajectory optimizer figures"; departures are stated field by field.
struct BackEndOptions {
  /// Piece count and initial durations (continuous-profile time / 1.0 s, >= 3 pieces).
  WarmStartOptions warm_start;
  /// The inner solver (memory 256, relative decrease 1e-4 over 3, up to 8000 iterations).
  LbfgsOptions lbfgs;
  /// The outer PHR-ALM loop on FK(s_f) = p_e, eq. (7).
  AugmentedLagrangianOptions alm;
  /// The end-effector tolerances of a success (the validator's: 0.01 m / 0.02 rad).
  double ee_position_tolerance_m = 0.01;
  double ee_orientation_tolerance_rad = 0.02;
  /// Wall-clock bound on one Optimize call (s), warm start to the final check (the check
  /// itself, a few ms, may end past it). A run that reaches it returns its last iterate:
  /// kSuccess if that passes, else kNotConverged ("time limit ... reached; ..."). Not in the
  /// reference code. 2 s is above the p95 of every benchmark cell on the 2-core VM (1.85 s
  /// for large Tables tasks, Release, one thread; docs/benchmarks.md).
  double time_limit_s = 2.0;
};

/// Throws std::invalid_argument "<owner>: <field> ..." naming the first field out of range
/// (the L-BFGS, warm start and ALM options included).
void CheckBackEndOptions(const BackEndOptions& options, std::string_view owner);

}  // namespace topay
