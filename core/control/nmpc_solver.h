#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include "core/control/base_tracking_cost.h"
#include "core/control/control_command.h"
#include "core/control/joint_tracking_cost.h"
#include "core/control/nmpc_options.h"
#include "core/control/nmpc_summary.h"
#include "core/control/reference_horizon.h"
#include "core/control/tracker_limits.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// The NMPC of the trajectory tracker (issue 19; docs/control.md), solved with Ceres
/// (Levenberg-Marquardt, dense normal Cholesky, one thread).
///
/// Model: unicycle base (x, y, yaw; inputs v, omega; RolloutUnicycle) and N joints as
/// integrators of their velocities, over horizon_steps steps of step_s. The joints are linear
/// and decoupled from the base and from each other, so the problem splits exactly into the
/// base problem (2 N inputs, nonlinear; BaseTrackingCost) and one linear problem per joint
/// (N inputs; JointTrackingCost), each a small dense Ceres problem built once and reused.
///
/// Limits, exact or penalised:
///   - exact (Ceres parameter bounds): |v| <= v_max, |omega| <= omega_max, |qd_j| <= qd_max,j.
///     They are boxes on the decision variables (the inputs), which is what Ceres bounds
///     express exactly and cheaply (projected trust-region steps, no extra residuals).
///   - penalties (weight limit_weight on the squared excess): the rates |u_k - u_k-1| / dt
///     <= a_max, beta_max, qdd_max,j and the coupled |v| / v_max + |omega| / omega_max <= 1.
///     They couple two inputs or two components, so they are not boxes in the inputs
///     (parameterising by rates instead would turn the speed limits into sums, not boxes).
///   - then every returned input is projected (ProjectInputSequence) onto the exact set of
///     all limits, chained from the last command sent: whatever the optimizer or the fallback
///     gives, every command satisfies every limit. The penalties keep the projection's moves
///     small, so the projected plan stays close to the optimum.
///
/// Warm start: the previous solution shifted by control_period_s (ShiftInputSequence); the
/// first solve (or after ResetWarmStart) holds the last command. A solve over time_budget_s
/// (Ceres's max_solver_time_in_seconds gets what remains of it) or failed returns the shifted
/// previous solution instead (projected like any other), counted in the summary.
///
/// Continuity: the first input's rate is taken against the last command sent (one
/// control_period_s earlier), so a new reference never makes the command jump.
///
/// Allocation: the problems, cost functions and buffers are built in the constructor; Solve
/// writes into them (Ceres itself allocates inside ceres::Solve). Not thread-safe.
class NmpcSolver {
 public:
  /// Throws std::invalid_argument for bad options (NmpcOptions::Check) or limits.
  NmpcSolver(const NmpcOptions& options, const TrackerLimits& limits);
  ~NmpcSolver();
  NmpcSolver(const NmpcSolver&) = delete;
  NmpcSolver& operator=(const NmpcSolver&) = delete;

  /// One solve from `state` (already predicted over the latency, see PredictState) against
  /// `reference` (sampled at the horizon's times from that state's time), continuous with
  /// `last_command` (the command sent one control period ago). Returns the projected input
  /// sequence; its column 0 is the command to send.
  const InputSequence& Solve(const WholeBodyState& state, const ReferenceHorizon& reference,
                             const ControlCommand& last_command);

  /// Forget the previous solution: the next warm start holds the last command (a new
  /// trajectory id). Counted in the summary.
  void ResetWarmStart();

  /// Changes time_budget_s (finite, > 0; else std::invalid_argument naming it).
  void set_time_budget_s(double budget_s);

  const InputSequence& solution() const { return solution_; }
  const NmpcSummary& summary() const { return summary_; }
  const NmpcOptions& options() const { return options_; }
  const TrackerLimits& limits() const { return limits_; }

 private:
  void PrepareWarmStart(const ControlCommand& last_command);
  /// Solves one problem with what remains of the budget; false if it failed.
  bool SolveProblem(ceres::Problem* problem, double remaining_s, int* iterations,
                    double* initial_cost, double* final_cost);

  NmpcOptions options_;
  TrackerLimits limits_;
  int num_joints_;
  InputSequence solution_;
  InputSequence warm_start_;
  bool has_solution_ = false;

  // Decision variables Ceres works on in place: base (v_k, omega_k) interleaved, and one
  // contiguous column of N velocities per joint.
  Eigen::Matrix2Xd base_inputs_;
  Eigen::MatrixXd joint_inputs_;  ///< N x num_joints.

  BaseTrackingCost* base_cost_ = nullptr;            ///< Owned by base_problem_.
  std::unique_ptr<ceres::Problem> base_problem_;
  std::vector<JointTrackingCost*> joint_costs_;      ///< Owned by joint_problems_.
  std::vector<std::unique_ptr<ceres::Problem>> joint_problems_;
  ceres::Solver::Options solver_options_;
  ceres::Solver::Summary ceres_summary_;
  NmpcSummary summary_;
};

}  // namespace topay
