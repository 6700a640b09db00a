#pragma once

#include <Eigen/Core>

#include "core/optimization/trajectory_objective.h"
#include "core/planning/whole_body_path.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_rates.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Options of MakeWarmStart. Defaults: the authors' code's figures.
struct WarmStartOptions {
  /// Piece count M = ceil(continuous profile duration / piece_duration_s), clamped to
  /// [min_pieces, max_pieces] (authors' code: total time / 1.5 s, at least 3 pieces). The
  /// continuous profile drives the whole path without stopping at its vertices
  /// (WarmStart::continuous_duration_s); the rest-to-rest profile that times the warm start
  /// stops at every turn and gave about twice the pieces the optimized trajectory needs.
  /// 1.0 s of the continuous profile: ~0.65 x the pieces of 1.5 s of the rest-to-rest one, at
  /// the same success rate (1.5 s of the continuous profile lost a few points on Tables;
  /// docs/benchmarks.md, "Sixth measurement").
  double piece_duration_s = 1.0;
  int min_pieces = 3;
  int max_pieces = 64;  ///< A guard against runaway problem sizes.
  /// The trapezoidal profiles use this fraction of every rate limit (v, a, omega, beta, q',
  /// q''). 1: the limits themselves.
  double rate_fraction = 1.0;
  /// The path's first state must match the start within these (m; rad, yaw and joints).
  double start_tolerance_m = 0.05;
  double start_tolerance_rad = 0.05;
  /// A path with no motion at all still gets this duration (s), so the arm can settle.
  double min_duration_s = 1.0;
};

/// Throws std::invalid_argument ("MakeWarmStart: <option> must ...") unless piece_duration_s
/// > 0, 1 <= min_pieces <= max_pieces, rate_fraction in (0, 1] and min_duration_s > 0.
void CheckWarmStartOptions(const WarmStartOptions& options);

/// The optimizer's initial guess (paper Sec. III-C): piece durations,
/// waypoints and the free end in the arc length-yaw variables, and stage 1's path reference.
struct WarmStart {
  int num_pieces = 0;
  Eigen::VectorXd durations_s;  ///< M, all equal: the profile's duration / M.
  Eigen::MatrixXd waypoints;    ///< D x (M - 1): s, yaw (unwrapped), q at the inner boundaries.
  Eigen::VectorXd end;          ///< D: s_f, yaw_f, q_f (the path's last state).
  PathReference reference;      ///< At every sample (j, l): see PathReference.
  /// The profile along the path: arc length (signed) and time of every path state.
  Eigen::VectorXd path_arc_length_m;
  Eigen::VectorXd path_times_s;
  double total_duration_s = 0.0;
  /// The piece count's duration: for each quantity (arc length, yaw, every joint) one
  /// rest-to-rest trapezoid over its total travel along the path, the longest (at least
  /// min_duration_s).
  double continuous_duration_s = 0.0;
};

/// Builds the warm start from a front-end path (states with x, y, yaw, q) and the start state:
///  - arc length s along the base path, signed (negative when the base drives backwards
///    relative to its yaw; turn-in-place states keep s), yaw unwrapped from the start's yaw;
///  - times from trapezoidal velocity profiles, rest to rest, over each run of consecutive
///    steps of one kind (driving, or turning in place / moving only the arm): the run takes
///    the longest of the trapezoid times of its base distance (v_max, a_max), yaw change
///    (omega_max, beta_max) and every joint's travel (q'_max, q''_max), and its states are
///    timed along the trapezoid of the quantity that takes longest;
///  - M from the continuous profile's duration (WarmStartOptions), equal durations (the
///    rest-to-rest profile's total / M), waypoints (s, yaw, q)
///    interpolated linearly in time at the piece boundaries; head = start at rest (the path's
///    first state is replaced by the start), tail = the path's last state at rest;
///  - the reference for stage 1 at each sample time (j + l / K) T / M.
/// Throws std::invalid_argument naming the problem for an empty path, states of the wrong
/// joint count or not finite, a path that does not begin at the start, or bad limits/options.
WarmStart MakeWarmStart(const WholeBodyPath& path, const WholeBodyState& start,
                        const BaseLimits& base_limits, const JointLimits& joint_limits,
                        int panels_per_piece, const WarmStartOptions& options = {});

/// MakeWarmStart from a moving start (issue 18): as above, except that the first run, if it
/// drives in the direction of start_rates.v_mps (the front end's lead-in does), is timed by a
/// profile that begins at |v| (accelerate to the peak, cruise, brake; or brake alone when the
/// run is shorter than the braking distance), so that the first piece's waypoint lies where
/// the moving base gets to, not where a base starting at rest would. The other rates (omega,
/// a, beta, qd, qdd) do not change the timing: they enter the optimizer's head only.
/// Rest rates give exactly the rest warm start. Throws as above, and for non-finite rates.
WarmStart MakeWarmStart(const WholeBodyPath& path, const WholeBodyState& start,
                        const WholeBodyRates& start_rates, const BaseLimits& base_limits,
                        const JointLimits& joint_limits, int panels_per_piece,
                        const WarmStartOptions& options = {});

}  // namespace topay
