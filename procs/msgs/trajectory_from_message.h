#pragma once
// A trajectory message back into the core trajectory, exactly: the MINCO s = 3 problem whose
// solution the message's coefficients are (head, tail, waypoints, durations) is recovered from
// the coefficients and solved again, so that receivers get x, y and every derivative
// (ArcYawTrajectory::Evaluate). Coefficients that are not such a solution are rejected.

#include <optional>
#include <string>

#include "core/trajectory/arc_yaw_trajectory.h"
#include "procs/msgs/convert_trajectory.h"

namespace topay::msgs {

struct TrajectoryRebuildOptions {
  /// K, the Simpson panels per piece of the x, y integration (the planner's
  /// trajectory.panels_per_piece, config/planner/topay.yaml: 12).
  ArcYawTrajectory::Options trajectory;
  /// Largest accepted difference between the re-solved and the received coefficients, relative
  /// to their size: max |c'_jk - c_jk| T_j^k <= tolerance * max(1, max |c_jk| T_j^k) over the
  /// pieces j, the powers k and the dimensions (each coefficient weighted by what it adds to the
  /// value at the end of its piece). A solved trajectory comes back to ~1e-12.
  double coefficient_tolerance = 1e-6;
  /// Largest accepted |yaw0_rad - yaw(0)|, rad.
  double yaw0_tolerance_rad = 1e-6;
  /// Shortest and longest accepted piece, s. Beyond them the MINCO problem is so ill-conditioned
  /// that a trajectory accepted once no longer re-solves to itself when sent again (found by
  /// tests/fuzz/trajectory_message_fuzz.cc: a 9e-20 s piece, a 135,001 s one); the planner's
  /// pieces last 0.1-5 s.
  double min_piece_duration_s = 1e-3;
  double max_piece_duration_s = 100.0;
};

/// The boundary data of the MINCO problem a PolyTrajectory solves: head and tail (D x 3: value,
/// 1st, 2nd derivative at t = 0 and at the end), waypoints (D x (M - 1): values at the inner
/// piece boundaries) and the durations.
struct MincoBoundary {
  Eigen::MatrixXd head;
  Eigen::MatrixXd tail;
  Eigen::MatrixXd waypoints;
  Eigen::VectorXd durations_s;
};

/// Reads the boundary data off the coefficients (no check).
MincoBoundary BoundaryOf(const PolyTrajectory& poly);

/// The relative coefficient difference of `coefficients` from poly's (see
/// TrajectoryRebuildOptions::coefficient_tolerance); shapes must agree. +inf when a weighted
/// coefficient of poly exceeds max double / 1024 (its values would overflow when evaluated) or
/// one of `coefficients` is not finite (a re-solve that overflowed).
double RelativeCoefficientError(const PolyTrajectory& poly, const Eigen::MatrixXd& coefficients);

/// The core trajectory the message carries: BoundaryOf, ArcYawTrajectory::Update from
/// poly.p0_W_m, then the checks. nullopt with *error naming the trajectory (its id) and the
/// reason if yaw0_rad disagrees with the yaw polynomial at 0, the problem cannot be solved, or
/// the re-solved coefficients differ from the message's (not a MINCO s = 3 solution).
std::optional<ArcYawTrajectory> ToArcYaw(const PolyTrajectory& poly, const TrajectoryRebuildOptions& options,
                                         std::string* error);

}  // namespace topay::msgs
