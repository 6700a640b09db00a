#pragma once

#include <stop_token>
#include <string>
#include <string_view>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/field_feasibility.h"
#include "core/optimization/flatness_trajectory.h"
#include "core/optimization/lbfgs_solve.h"
#include "core/optimization/trajectory_objective.h"
#include "core/optimization/warm_start.h"
#include "core/planning/whole_body_path.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// Which trajectory the optimizer builds: TopAY's arc length-yaw MINCO (the default), or the
/// REMANI-style flatness baseline (x, y, q as MINCO, yaw = atan2(dy, dx); flatness_optimizer.h).
enum class TrajectoryParameterisation { kArcLengthYaw, kFlatness };

/// Options of TrajectoryOptimizer, Ceres style. Defaults: the facts sheet's "Trajectory
/// optimizer figures"; departures are stated field by field.
struct TrajectoryOptimizerOptions {
  /// Stage 2's objective: jerk weights, time weight 50, K = 12, the penalty weights, margins
  /// and smoothing (core/optimization/trajectory_objective.h, sample_penalties.h).
  TrajectoryObjectiveOptions objective;
  /// Piece count and initial durations (continuous-profile time / 1.0 s, >= 3 pieces).
  WarmStartOptions warm_start;
  /// The inner solver (memory 256, relative decrease 1e-4 over 3, up to 8000 iterations).
  LbfgsOptions lbfgs;

  // ---- Stage 1: fit the initial path (facts sheet) ---------------------------------------
  /// Run stage 1: jerk + time + path fit + the base kinodynamic penalties (v-omega, a, beta)
  /// and the joint limit penalties (position, velocity, acceleration), no collision and no
  /// end-effector term.
  bool run_stage1 = true;
  /// L-BFGS iterations of stage 1 (a fit to hand to stage 2, not a converged solution).
  int stage1_max_iterations = 100;

  // ---- Stage 2: PHR augmented Lagrangian for FK(s_f) = p_e (eq. (7)) ---------------------
  double alm_rho_initial = 1e4;
  double alm_rho_growth = 10.0;  ///< rho *= growth after every outer iteration...
  double alm_rho_max = 1e10;     ///< ...up to this.
  int alm_max_outer_iterations = 8;
  /// The outer loop stops once |p_WE - p_goal| and the rotation angle are below these. Half
  /// of the success tolerances, so the end state keeps a margin (the facts sheet's 0.01 m is
  /// the success tolerance below).
  double alm_position_tolerance_m = 0.005;
  double alm_orientation_tolerance_rad = 0.01;

  /// If the result is infeasible on the fields (a penalty's optimum lies beyond its hard
  /// limit, pulled by the end-effector term or by another penalty, or the trajectory peaks
  /// between two samples), the weights of the violated terms are multiplied by
  /// penalty_escalation_factor, the violated thresholds are tightened (PenaltyTightening:
  /// a clearance by its shortfall + clearance_escalation_step_m, the joint margin by the
  /// excess + joint_escalation_step_rad, the rate limits by 1 / ratio x (1 -
  /// rate_escalation_step)) and the ALM continues, up to max_penalty_escalations times. Not
  /// in the reference code.
  int max_penalty_escalations = 2;
  double penalty_escalation_factor = 10.0;
  double clearance_escalation_step_m = 0.005;
  double joint_escalation_step_rad = 0.005;
  double rate_escalation_step = 0.01;

  // ---- Success -----------------------------------------------------------------------------
  /// The end-effector tolerances of a success (the and the validator's).
  double ee_position_tolerance_m = 0.01;
  double ee_orientation_tolerance_rad = 0.02;
  /// The final trajectory must pass this check on the fields (hard limits, no safety factor).
  FieldFeasibilityOptions feasibility;
  /// Wall-clock bound on one Optimize call (s), warm start to the final check (the check
  /// itself, a few ms, may end past it). A run that reaches it returns its last iterate:
  /// kSuccess if that passes, else kNotConverged ("time limit ... reached; ..."). Not in the
  /// reference code. 2 s is above the p95 of every benchmark cell on the 2-core VM (1.85 s
  /// for large Tables tasks, Release, one thread; docs/benchmarks.md).
  double time_limit_s = 2.0;

  /// kFlatness runs FlatnessOptimizer instead (same problem, path and statuses): it takes
  /// from these options the warm start, L-BFGS, ALM, tolerances, time limit, penalty
  /// options, jerk and time weights, and keeps its own sampling (16 trapezoid panels per
  /// piece, dense at the stops) and minimum-speed defaults. Its summary has no arc
  /// length-yaw data: use Sampled(), not MakeTrajectory().
  TrajectoryParameterisation parameterisation = TrajectoryParameterisation::kArcLengthYaw;
};

/// Throws std::invalid_argument naming the first option out of range (the L-BFGS options
/// included; the penalty options are checked by the TrajectoryOptimizer constructor).
void CheckTrajectoryOptimizerOptions(const TrajectoryOptimizerOptions& options);

enum class TrajectoryOptimizerStatus {
  kSuccess,        ///< End effector within tolerance and the trajectory feasible on the fields.
  kNotConverged,   ///< Ran, but the end-effector constraint, a limit or a clearance is not met
                   ///< (or the time limit was reached): see reason.
  kCancelled,      ///< The stop token was triggered.
  kInvalidInput,   ///< NaN, wrong sizes, a bad path, or a target no robot state can reach.
};
std::string_view ToString(TrajectoryOptimizerStatus status);

/// The problem's inputs besides the fields and the robot (paper Sec. III-C).
struct TrajectoryProblem {
  WholeBodyState start;           ///< At rest; s(0) = 0.
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();  ///< p_e of eq. (7).
  BaseLimits base_limits;         ///< Caller-chosen (the benchmark: omega_max 1.25).
};

/// What Optimize did, and the trajectory's data (enough to rebuild it: MakeTrajectory).
struct TrajectoryOptimizerSummary {
  TrajectoryOptimizerStatus status = TrajectoryOptimizerStatus::kInvalidInput;
  /// Empty on success; otherwise what failed, e.g. "end-effector error 0.034 m / 0.002 rad
  /// above 0.01 m / 0.02 rad" or "path: path state 3 is not finite".
  std::string reason;

  // The trajectory (valid when num_pieces > 0: after a run, successful or not).
  int num_pieces = 0;
  int panels_per_piece = 12;
  Eigen::Vector2d p0_W = Eigen::Vector2d::Zero();
  Eigen::MatrixXd head;       ///< D x 3 (start at rest).
  Eigen::MatrixXd tail;       ///< D x 3: column 0 = (s_f, yaw_f, q_f), rest zero.
  Eigen::MatrixXd waypoints;  ///< D x (M - 1).
  Eigen::VectorXd durations_s;
  double duration_s = 0.0;

  // End effector at the end.
  double ee_position_error_m = 0.0;
  double ee_orientation_error_rad = 0.0;

  // Work done.
  int outer_iterations = 0;       ///< ALM outer iterations of stage 2.
  int stage1_iterations = 0;      ///< L-BFGS iterations.
  int stage2_iterations = 0;      ///< L-BFGS iterations over all outer iterations.
  int objective_evaluations = 0;  ///< Both stages.
  int penalty_escalations = 0;    ///< Times violated terms' weights were raised (x factor).
  double final_rho = 0.0;
  ObjectiveBreakdown final_cost;  ///< Stage 2's objective at the solution.
  FieldFeasibilityReport feasibility;

  // Wall-clock (s).
  double warm_start_s = 0.0;
  double stage1_s = 0.0;
  double stage2_s = 0.0;  ///< Including the field checks between penalty escalations.
  double check_s = 0.0;   ///< The field checks (CheckFeasibilityOnFields) alone.
  double total_s = 0.0;

  /// Which trajectory the data describe: kArcLengthYaw (head, tail, waypoints, p0_W above)
  /// or kFlatness (`flatness`; durations_s and duration_s are filled in both cases).
  TrajectoryParameterisation parameterisation = TrajectoryParameterisation::kArcLengthYaw;
  FlatnessTrajectoryData flatness;

  bool success() const { return status == TrajectoryOptimizerStatus::kSuccess; }
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

/// The planner's back end (paper Sec. III-B..C, issue 4 items 3-4): the arc length-yaw MINCO
/// trajectory optimization of eqs. (6)-(23) from a front-end whole-body path.
///  1. Warm start (MakeWarmStart): M pieces, durations from trapezoidal profiles, waypoints
///     and the free end from the path.
///  2. Stage 1 (facts sheet): fit the path (jerk, time, path fit, kinodynamic penalties).
///  3. Stage 2: every term; the end-effector constraint FK(s_f) = p_e (position and
///     orientation) by PHR-ALM: minimise with lambda, rho; lambda += rho r; rho *= 10 up to
///     1e10, until |r| is within tolerance. Inner solver: Ceres' GradientProblemSolver with
///     L-BFGS and a Wolfe line search (lbfgs_solve.h). If the result is infeasible on the
///     fields, the violated terms' weights are raised x10 and the ALM continues (at most
///     twice).
///  4. Success = end effector within 1 cm / 0.02 rad and the trajectory feasible on the fields
///     at 10 ms samples (field_feasibility.h).
///
/// Cancellation: `stop` is polled by every objective evaluation and after every L-BFGS
/// iteration; a cancelled call returns kCancelled with the last iterate's trajectory.
///
/// The kinematics (and its model) and the fields must outlive this object. Optimize is const
/// and thread-safe (every call builds its own objective).
class TrajectoryOptimizer {
 public:
  /// Throws std::invalid_argument for options out of range (CheckTrajectoryOptimizerOptions,
  /// and the penalty options as SamplePenalties checks them).
  TrajectoryOptimizer(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                      const SignedDistanceField3& arm_field,
                      TrajectoryOptimizerOptions options = {});

  /// Never throws for bad input: an invalid start, goal, limits or path gives kInvalidInput
  /// with the reason; an unreachable target (height out of the arm's reach, or inside an
  /// obstacle on the 3D field) too.
  TrajectoryOptimizerSummary Optimize(const TrajectoryProblem& problem,
                                      const WholeBodyPath& initial_path,
                                      std::stop_token stop = {}) const;

  const TrajectoryOptimizerOptions& options() const { return options_; }
  /// The heights (m, world z) the end-effector frame's origin can reach: joint 1's height
  /// -+ the chain's length bound from joint 1 to E.
  double min_reach_height_m() const { return min_reach_height_m_; }
  double max_reach_height_m() const { return max_reach_height_m_; }

 private:
  struct Run;
  /// The reason the inputs are unusable, or "" if they are fine.
  std::string CheckProblem(const TrajectoryProblem& problem) const;
  void RunStages(Run* run) const;
  /// ALM outer iterations from (lambda, rho) until the end effector is within the ALM
  /// tolerances or the outer limit; false if cancelled or out of time.
  bool RunAugmentedLagrangian(Run* run, Vector6d* lambda, double* rho) const;
  /// Evaluates x, copies the trajectory into the summary and checks it on the fields; true
  /// if it is a success.
  bool CheckResult(Run* run) const;
  void Finish(Run* run) const;

  const Kinematics& kinematics_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  TrajectoryOptimizerOptions options_;
  double min_reach_height_m_ = 0.0;
  double max_reach_height_m_ = 0.0;
};

}  // namespace topay
