#pragma once

#include <stop_token>
#include <string>

#include <Eigen/Core>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/flatness_objective.h"
#include "core/optimization/flatness_trajectory.h"
#include "core/optimization/lbfgs_solve.h"
#include "core/optimization/trajectory_optimizer.h"
#include "core/optimization/warm_start.h"
#include "core/planning/whole_body_path.h"
#include "core/robot/kinematics.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// Options of FlatnessOptimizer. Defaults as TrajectoryOptimizerOptions where they overlap.
struct FlatnessOptimizerOptions {
  FlatnessObjectiveOptions objective;
  WarmStartOptions warm_start;
  LbfgsOptions lbfgs;  ///< memory, max_iterations, relative decrease (Wolfe constants too).
  double alm_rho_initial = 1e4;
  double alm_rho_growth = 10.0;
  double alm_rho_max = 1e10;
  int alm_max_outer_iterations = 8;
  double alm_position_tolerance_m = 0.005;
  double alm_orientation_tolerance_rad = 0.01;
  double ee_position_tolerance_m = 0.01;
  double ee_orientation_tolerance_rad = 0.02;
  /// The final check samples the trajectory every check_period_s with the sample penalties at
  /// 100 % of the rate limits and no joint margin; any active term is a violation.
  double check_period_s = 0.01;
  double time_limit_s = 2.0;
};

/// Outcome of FlatnessOptimizer::Optimize (same statuses as TrajectoryOptimizer).
struct FlatnessOptimizerSummary {
  TrajectoryOptimizerStatus status = TrajectoryOptimizerStatus::kInvalidInput;
  std::string reason;  ///< Empty on success.
  FlatnessTrajectoryData trajectory;  ///< Valid when num_pieces > 0.
  int num_pieces = 0;
  double duration_s = 0.0;
  double ee_position_error_m = 0.0;
  double ee_orientation_error_rad = 0.0;
  int outer_iterations = 0;
  int iterations = 0;
  int objective_evaluations = 0;
  FlatnessBreakdown final_cost;
  PenaltyValues check_violations{};  ///< Per term: the worst sample penalty in the check.
  double total_s = 0.0;

  bool success() const { return status == TrajectoryOptimizerStatus::kSuccess; }
  /// The trajectory for TrajectoryValidator (holds the data by value). Throws
  /// std::invalid_argument if num_pieces == 0.
  SampledTrajectory Sampled() const;
  std::string Report() const;
};

/// The REMANI-style flatness baseline (issue 4, item 7) behind the same problem interface as
/// TrajectoryOptimizer (TrajectoryProblem + a front-end WholeBodyPath):
///  1. warm start: MakeWarmStart's durations and joints, base positions from its path
///     reference at the piece ends, psi_f = the path's last yaw;
///  2. PHR-ALM on the end-effector constraint (eq. (7)) with L-BFGS (Ceres, Wolfe), all the
///     FlatnessObjective terms (no stage 1 path fit, no penalty escalation);
///  3. success = end effector within tolerance and the dense sample check clean.
/// Forward driving only (eta = +1). Optimize is const and thread-safe.
class FlatnessOptimizer {
 public:
  /// Throws std::invalid_argument for options out of range.
  FlatnessOptimizer(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                    const SignedDistanceField3& arm_field, FlatnessOptimizerOptions options = {});

  /// Never throws for bad input: kInvalidInput with the reason.
  FlatnessOptimizerSummary Optimize(const TrajectoryProblem& problem,
                                    const WholeBodyPath& initial_path,
                                    std::stop_token stop = {}) const;

  const FlatnessOptimizerOptions& options() const { return options_; }

 private:
  std::string CheckProblem(const TrajectoryProblem& problem) const;
  void Check(const TrajectoryProblem& problem, FlatnessOptimizerSummary* summary) const;

  const Kinematics& kinematics_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  FlatnessOptimizerOptions options_;
};

}  // namespace topay
