#pragma once

#include <string>
#include <string_view>

#include <Eigen/Core>

#include "core/optimization/field_feasibility.h"
#include "core/optimization/flatness_trajectory.h"
#include "core/optimization/sample_penalties.h"
#include "core/optimization/trajectory_objective.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// Which trajectory a back end builds: TopAY's arc length-yaw MINCO (TrajectoryOptimizer, the
/// default), or the REMANI-style flatness baseline (x, y, q as MINCO, yaw = atan2(dy, dx);
/// FlatnessOptimizer).
enum class TrajectoryParameterisation { kArcLengthYaw, kFlatness };

enum class BackEndStatus {
  kSuccess,        ///< End effector within tolerance and the trajectory feasible on the fields.
  kNotConverged,   ///< Ran, but the end-effector constraint, a limit or a clearance is not met
                   ///< (or the time limit was reached): see reason.
  kCancelled,      ///< The stop token was triggered.
  kInvalidInput,   ///< NaN, wrong sizes, a bad path, or a target no robot state can reach.
};
std::string_view ToString(BackEndStatus status);

/// What a back end's Optimize did, and the trajectory's data (enough to rebuild it:
/// MakeTrajectory or Sampled). One summary for both back ends; the fields one of them does
/// not fill keep their defaults (noted per field).
struct BackEndSummary {
  BackEndStatus status = BackEndStatus::kInvalidInput;
  /// Empty on success; otherwise what failed, e.g. "end-effector error 0.034 m / 0.002 rad
  /// above 0.01 m / 0.02 rad" or "path: path state 3 is not finite".
  std::string reason;

  /// Which trajectory the data describe: kArcLengthYaw (head, tail, waypoints, p0_W below)
  /// or kFlatness (`flatness`); num_pieces, durations_s and duration_s are filled in both.
  TrajectoryParameterisation parameterisation = TrajectoryParameterisation::kArcLengthYaw;

  // The trajectory (valid when num_pieces > 0: after a run, successful or not).
  int num_pieces = 0;
  int panels_per_piece = 12;  ///< Arc length-yaw: K of the x, y integration.
  Eigen::Vector2d p0_W = Eigen::Vector2d::Zero();
  Eigen::MatrixXd head;       ///< D x 3 (start at rest).
  Eigen::MatrixXd tail;       ///< D x 3: column 0 = (s_f, yaw_f, q_f), rest zero.
  Eigen::MatrixXd waypoints;  ///< D x (M - 1).
  Eigen::VectorXd durations_s;
  double duration_s = 0.0;
  FlatnessTrajectoryData flatness;  ///< kFlatness only.

  // End effector at the end.
  double ee_position_error_m = 0.0;
  double ee_orientation_error_rad = 0.0;

  // Work done.
  int outer_iterations = 0;       ///< ALM outer iterations (stage 2).
  int stage1_iterations = 0;      ///< L-BFGS iterations (arc length-yaw only: the path fit).
  int stage2_iterations = 0;      ///< L-BFGS iterations over all outer iterations.
  int objective_evaluations = 0;  ///< Both stages.
  int penalty_escalations = 0;    ///< Times violated terms' weights were raised (arc length-yaw).
  /// Arc length-yaw: stage 2 started again after a collapsed duration
  /// (TrajectoryOptimizerOptions::collapse_duration_fraction).
  int collapse_restarts = 0;
  /// Arc length-yaw: the uniform slow-down applied to the result (every duration x this;
  /// TrajectoryOptimizerOptions::max_time_stretch); 1 if none.
  double time_stretch = 1.0;
  double final_rho = 0.0;         ///< Arc length-yaw only.
  ObjectiveBreakdown final_cost;  ///< Stage 2's objective at the solution (no path fit).
  double final_min_speed_cost = 0.0;  ///< Flatness only: its minimum-speed term.
  /// Arc length-yaw: the final check on the fields (CheckFeasibilityOnFields).
  FieldFeasibilityReport feasibility;
  /// Arc length-yaw: the clearance relief near the start / goal inside the margins
  /// (EndpointRelief::Describe, e.g. "start base 0.031 m, arm max 0.072 m over the first
  /// 18 %"); "" if none was used. The flatness baseline uses none.
  std::string endpoint_relief;
  /// Flatness: per term, the worst sample penalty of its final dense check (> 0: violated).
  PenaltyValues check_violations{};

  // Wall-clock (s).
  double warm_start_s = 0.0;  ///< Arc length-yaw only.
  double stage1_s = 0.0;      ///< Arc length-yaw only.
  double stage2_s = 0.0;      ///< Including the field checks between penalty escalations.
  double check_s = 0.0;       ///< The field checks (CheckFeasibilityOnFields) alone.
  double total_s = 0.0;

  bool success() const { return status == BackEndStatus::kSuccess; }
  int inner_iterations() const { return stage1_iterations + stage2_iterations; }

  /// Rebuilds the arc length-yaw trajectory (allocates). Throws std::invalid_argument if
  /// num_pieces == 0 or the parameterisation is kFlatness.
  ArcYawTrajectory MakeTrajectory() const;
  /// The trajectory for TrajectoryValidator, either parameterisation (holds what it needs by
  /// value). Throws std::invalid_argument if num_pieces == 0.
  SampledTrajectory Sampled() const;

  /// A readable multi-line report.
  std::string Report() const;
};

}  // namespace topay
