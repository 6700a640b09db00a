#pragma once

#include <stop_token>
#include <string>
#include <string_view>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/back_end_options.h"
#include "core/optimization/back_end_summary.h"
#include "core/optimization/endpoint_relief.h"
#include "core/optimization/field_feasibility.h"
#include "core/optimization/trajectory_back_end.h"
#include "core/optimization/trajectory_objective.h"
#include "core/optimization/trajectory_problem.h"
#include "core/planning/whole_body_path.h"
#include "core/robot/kinematics.h"

namespace topay {

/// Options of TrajectoryOptimizer, Ceres style: the shared BackEndOptions (warm start,
/// L-BFGS, ALM, success tolerances, time limit) and its own. Defaults: the authors' code's
/// "Trajectory optimizer figures"; departures are stated field by field.
struct TrajectoryOptimizerOptions : BackEndOptions {
  /// Stage 2's objective: jerk weights, time weight 50, K = 12, the penalty weights, margins
  /// and smoothing (core/optimization/trajectory_objective.h, sample_penalties.h).
  TrajectoryObjectiveOptions objective;

  // ---- Stage 1: fit the initial path (the authors' code) ---------------------------------------
  /// Run stage 1: jerk + time + path fit + the base kinodynamic penalties (v-omega, a, beta)
  /// and the joint limit penalties (position, velocity, acceleration), no collision and no
  /// end-effector term.
  bool run_stage1 = true;
  /// L-BFGS iterations of stage 1 (a fit to hand to stage 2, not a converged solution).
  int stage1_max_iterations = 100;

  // ---- Stage 2: PHR augmented Lagrangian for FK(s_f) = p_e (eq. (7), BackEndOptions::alm) --
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

  // ---- Time stretch (ours) -----------------------------------------------------------------
  /// A result whose only shortfall on the fields is a rate limit (v-omega, a, beta, q', q''),
  /// from a start at rest, is slowed down uniformly: every piece duration x k. The path in
  /// space is unchanged: with zero velocity and acceleration at both ends, the MINCO
  /// trajectory of the durations k T_j is the old one at t / k (the minimum-jerk conditions
  /// (15)-(20) are invariant under a uniform time scaling), so velocities fall by 1 / k and
  /// accelerations by 1 / k^2 while every clearance, joint position and the end state stay.
  /// k is chosen from the worst rate (ratio / target for a velocity, sqrt of it for an
  /// acceleration; target 1 - rate_escalation_step), up to max_time_stretch in total, and
  /// the check repeated (at most 4 times). 1: never stretch. Tried after each ALM run, before
  /// a penalty escalation.
  double max_time_stretch = 2.0;

  // ---- A collapsed duration (ours, finding 29) ---------------------------------------------
  /// A stage 2 that ends with the end effector off target and the duration below
  /// collapse_duration_fraction x the warm start's fell into the degenerate optimum of a start
  /// whose end effector is already within centimetres of the target: at the ALM's first rho
  /// the error cost less than any motion's jerk and time, so the end state stayed at the
  /// start and the duration shrank towards 0, where its gradient vanishes (eq. (21)); no
  /// larger rho brings it back. Both stages then run again from the warm start (multipliers,
  /// penalty weights and thresholds reset) with rho x collapse_rho_factor, at most
  /// max_collapse_restarts times (0: never). Finding 29's case (2.5 cm off target, the arm
  /// to move 0.6 rad; tests/core/optimization/trajectory_optimizer_collapse_test.cc): rho
  /// 1e4 collapsed to 0.17 ms, 1e6 converged.
  double collapse_duration_fraction = 0.05;
  double collapse_rho_factor = 100.0;
  int max_collapse_restarts = 2;

  // ---- Endpoints inside the margins (TrajectoryProblem::exact_prefix_states / suffix) ------
  /// With exact_prefix_states > 0 (exact_suffix_states > 0) the clearance thresholds of the
  /// penalties and of the field check are relieved by the start's (the path's last state's)
  /// deficit plus slack_m, ramped out over the path's exact stretch and one piece more
  /// (EndpointRelief). Not in the reference code.
  EndpointReliefOptions endpoint_relief;

  // ---- Success -----------------------------------------------------------------------------
  /// The final trajectory must pass this check on the fields (hard limits, no safety factor;
  /// relieved near an endpoint that lies inside the margins, as the penalties are).
  FieldFeasibilityOptions feasibility;

  /// Which back end MakeTrajectoryBackEnd (back_end_factory.h) builds from these options:
  /// kArcLengthYaw, this TrajectoryOptimizer, or kFlatness, FlatnessOptimizer with the shared
  /// BackEndOptions, the penalty options, jerk and time weights and the feasibility check's
  /// sample period taken from these (its own sampling, 16 trapezoid panels per piece dense
  /// at the stops, and minimum-speed defaults stay). TrajectoryOptimizer itself rejects
  /// kFlatness.
  TrajectoryParameterisation parameterisation = TrajectoryParameterisation::kArcLengthYaw;
};

/// Throws std::invalid_argument naming the first option out of range (the shared
/// BackEndOptions included; the penalty options are checked by the TrajectoryOptimizer
/// constructor).
void CheckTrajectoryOptimizerOptions(const TrajectoryOptimizerOptions& options);

/// The planner's back end (paper Sec. III-B..D): the arc length-yaw MINCO
/// trajectory optimization of eqs. (6)-(23) from a front-end whole-body path.
///  1. Warm start (MakeWarmStart): M pieces, durations from trapezoidal profiles, waypoints
///     and the free end from the path.
///  2. Stage 1 (the authors' code): fit the path (jerk, time, path fit, kinodynamic penalties).
///  3. Stage 2: every term; the end-effector constraint FK(s_f) = p_e (position and
///     orientation) by PHR-ALM: minimise with lambda, rho; lambda += rho r; rho *= 10 up to
///     1e10, until |r| is within tolerance. Inner solver: Ceres' GradientProblemSolver with
///     L-BFGS and a Wolfe line search (lbfgs_solve.h). If the result is infeasible on the
///     fields, the violated terms' weights are raised x10 and the ALM continues (at most
///     twice).
///  4. Success = end effector within 1 cm / 0.02 rad and the trajectory feasible on the fields
///     at 10 ms samples (field_feasibility.h).
/// A start (goal) that the front end accepted inside the fields' margins, its path's first
/// (last) states validated exactly (TrajectoryProblem::exact_prefix_states / suffix), gets
/// its clearance margins relieved in steps 3 and 4 (EndpointRelief: the endpoint's deficit,
/// ramped out from it); the summary's endpoint_relief says so. The exact validator
/// (core/validate) stays the judge of the result.
///
/// Cancellation: `stop` is polled by every objective evaluation and after every L-BFGS
/// iteration; a cancelled call returns kCancelled with the last iterate's trajectory.
///
/// The kinematics (and its model) and the fields must outlive this object. Optimize is const
/// and thread-safe (every call builds its own objective).
class TrajectoryOptimizer : public TrajectoryBackEnd {
 public:
  /// Throws std::invalid_argument for options out of range (CheckTrajectoryOptimizerOptions,
  /// and the penalty options as SamplePenalties checks them) or parameterisation kFlatness.
  TrajectoryOptimizer(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                      const SignedDistanceField3& arm_field,
                      TrajectoryOptimizerOptions options = {});

  /// Never throws for bad input: an invalid start, goal, limits or path gives kInvalidInput
  /// with the reason; an unreachable target (height out of the arm's reach, or inside an
  /// obstacle on the 3D field) too, and exact_prefix_states / exact_suffix_states outside
  /// [0, path size].
  BackEndSummary Optimize(const TrajectoryProblem& problem, const WholeBodyPath& initial_path,
                          std::stop_token stop = {}) const override;
  TrajectoryParameterisation parameterisation() const override {
    return TrajectoryParameterisation::kArcLengthYaw;
  }

  const TrajectoryOptimizerOptions& options() const { return options_; }
  /// The heights (m, world z) the end-effector frame's origin can reach: joint 1's height
  /// -+ the chain's length bound from joint 1 to E.
  double min_reach_height_m() const { return reach_.min_z_m; }
  double max_reach_height_m() const { return reach_.max_z_m; }

 private:
  struct Run;
  /// Builds the warm start, the objective, the endpoint relief and the initial decision
  /// vector; false (with the summary's status and reason set) for a path the warm start
  /// cannot use.
  bool Prepare(const WholeBodyPath& initial_path, Run* run) const;
  /// The relief of the problem's exact path stretches (empty if it asks for none or its
  /// endpoints are clear of the margins), given to the objective and named in the summary.
  void PrepareEndpointRelief(const WholeBodyPath& initial_path, Run* run) const;
  /// Stage 1 and stage 2, both again from the warm start with rho x collapse_rho_factor while
  /// the duration collapsed (collapse_duration_fraction).
  void RunStages(Run* run) const;
  /// Stage 1: the path fit; false if cancelled or out of time.
  bool RunStage1(Run* run) const;
  /// After a failed CheckResult: the time stretch of max_time_stretch's comment if it
  /// applies; true if the stretched trajectory passes CheckResult (x then holds it), else x
  /// and the summary's check are as before.
  bool StretchTime(Run* run) const;
  /// Stage 2: ALM rounds from rho, zero multipliers, unit penalty weights and untightened
  /// thresholds, with penalty escalation, until a success (true), a feasible result or the
  /// escalation limit.
  bool RunStage2(double rho, Run* run) const;
  /// The last checked iterate misses the end effector with a duration below
  /// collapse_duration_fraction x the warm start's (and the run was neither cancelled nor out
  /// of time).
  bool DurationCollapsed(const Run& run) const;
  /// ALM outer iterations from (lambda, rho) until the end effector is within the ALM
  /// tolerances or the outer limit; false if cancelled or out of time.
  bool RunAugmentedLagrangian(Run* run, Vector6d* lambda, double* rho) const;
  /// Evaluates x and copies the trajectory into the summary; false if x does not evaluate.
  bool CopyTrajectory(Run* run) const;
  /// Evaluates x, copies the trajectory into the summary and checks it on the fields; true
  /// if it is a success.
  bool CheckResult(Run* run) const;
  void Finish(Run* run) const;
  /// The final status and reason of a run that was not cancelled and whose last iterate was
  /// checked.
  void Conclude(Run* run) const;

  const Kinematics& kinematics_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  TrajectoryOptimizerOptions options_;
  ReachHeights reach_;
};

}  // namespace topay
