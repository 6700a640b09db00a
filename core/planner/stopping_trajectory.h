#pragma once

#include <optional>
#include <string>

#include "core/robot/robot_model.h"
#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay {

/// Options of MakeStoppingTrajectory. Defaults: the validator's limit tolerances.
struct StoppingTrajectoryOptions {
  /// MINCO piece length (s): the stopping trajectory passes the time-scaled path at every
  /// piece boundary (0.1 s keeps it within about a millimetre of the path; the tests check).
  double piece_duration_s = 0.1;
  int max_pieces = 600;  ///< A guard against runaway sizes (60 s at 0.1 s).
  /// Simpson panels per piece of the x, y integration (ArcYawTrajectory::Options).
  int panels_per_piece = 12;
  /// The first stopping duration tried is the largest of min_duration_s and, per rate,
  /// duration_per_rate_ratio x rate / its acceleration limit (v / a_max, omega / beta_max,
  /// qd / qdd_max at t0): the time scaling's own deceleration then takes at most 1.5 /
  /// duration_per_rate_ratio of each acceleration limit. Every DOF stops together along the
  /// path, so a fast arm joint sets how far the base still goes (a stop from 0.36 m/s took
  /// 3.1 s in the replanning benchmark). 1.6 (94 %, lengthened when beyond a limit) halves
  /// that, but then the planner graph test's box 2.5 m ahead is avoided by a replan before any
  /// stop is due: that test must first place its box by the stop's own reach
  /// (docs/benchmarks.md, run D used 1.6).
  double min_duration_s = 0.3;
  double duration_per_rate_ratio = 3.0;
  /// A trajectory beyond a limit (checked every check_period_s as the validator does:
  /// WorstRateRatio <= 1 + limit_tolerance, joints within joint_position_tolerance_rad) is
  /// tried again lengthened by this factor, at most max_attempts times in all.
  double lengthen_factor = 1.3;
  int max_attempts = 10;
  double check_period_s = 0.01;
  double limit_tolerance = 0.01;
  double joint_position_tolerance_rad = 1e-9;
};

/// Throws std::invalid_argument ("StoppingTrajectoryOptions: <field> must ...") for a field
/// out of range.
void CheckStoppingTrajectoryOptions(const StoppingTrajectoryOptions& options);

/// The outcome of MakeStoppingTrajectory.
struct StoppingTrajectory {
  std::optional<ArcYawTrajectory> trajectory;  ///< Set on success.
  std::string reason;          ///< Empty on success, else why there is none.
  double duration_s = 0.0;     ///< Of the stopping trajectory.
  /// tau(T) - t0: how far along the current trajectory (its time) the robot stops.
  double path_time_used_s = 0.0;
  double worst_limit_ratio = 0.0;  ///< Largest value / limit over the checked samples.
  /// Largest base position distance (m) between the stopping trajectory at t and the current
  /// one at tau(t), over the checked samples: how closely it stays on the current path.
  double max_path_deviation_m = 0.0;
  int attempts = 0;
  bool follows_to_end = false;  ///< True if it follows the current trajectory to its end.

  bool success() const { return trajectory.has_value(); }
};

/// A trajectory that brings the robot to rest along the path it is on (issue 18): the
/// planner process's fallback when a replan fails or the path ahead is blocked.
///
/// From t0 on the current trajectory r(t) = [s, yaw, q](t) (an arc length-yaw MINCO, paper
/// Sec. III-B) it follows the same geometry, time-scaled: r_stop(t) = r(tau(t)) - [s(t0), 0, 0]
/// with tau(0) = t0 and
///   tau'(t) = 1 - (3 u^2 - 2 u^3),  u = t / T,  so  tau(t) = t0 + t - T (u^3 - u^4 / 2),
/// tau' falling from 1 to 0 with tau''(0) = tau''(T) = 0. By the chain rule
///   r_stop' = r'(tau) tau',  r_stop'' = r''(tau) tau'^2 + r'(tau) tau'',
/// so at t = 0 the rates equal r's (C2 with the current trajectory: head = r, r', r'' at t0)
/// and at t = T they vanish (at rest: the tail of conditions (18)-(20)); the robot stops
/// at tau(T) = t0 + T / 2. If that lies beyond the current trajectory's end (which is at
/// rest), it follows the current trajectory to its end instead (tau(t) = t0 + t).
///
/// The result is itself an ArcYawTrajectory in the same dimensions: MINCO pieces of
/// piece_duration_s whose waypoints are r(tau) at the piece boundaries (the minimum-jerk
/// interpolant of the time-scaled path), x, y integrated from p0 = the current trajectory's
/// (x, y) at t0 (eqs. (1)-(2)). It is checked against the base and joint limits at every
/// check_period_s (the validator's WorstRateRatio and joint position limits) and, while beyond
/// them, lengthened (T x lengthen_factor). Not checked for collisions: it stays on the path
/// the current trajectory was validated on (max_path_deviation_m says how closely).
///
/// Never throws for bad input: a result without trajectory and with the reason (t0 not
/// finite, a trajectory never updated, limits of the wrong size, the limits still exceeded
/// after max_attempts). Throws std::invalid_argument only for bad options.
StoppingTrajectory MakeStoppingTrajectory(const ArcYawTrajectory& current, double t0_s,
                                          const BaseLimits& base_limits,
                                          const JointLimits& joint_limits,
                                          const StoppingTrajectoryOptions& options = {});

}  // namespace topay
