#pragma once

#include <stop_token>
#include <string>

#include <Eigen/Core>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/back_end_options.h"
#include "core/optimization/back_end_summary.h"
#include "core/optimization/flatness_objective.h"
#include "core/optimization/flatness_trajectory.h"
#include "core/optimization/trajectory_back_end.h"
#include "core/optimization/trajectory_problem.h"
#include "core/planning/whole_body_path.h"
#include "core/robot/kinematics.h"

namespace topay {

/// Options of FlatnessOptimizer: the shared BackEndOptions (defaults as
/// TrajectoryOptimizerOptions') and its own objective and final check.
struct FlatnessOptimizerOptions : BackEndOptions {
  FlatnessObjectiveOptions objective;
  /// The final check samples the trajectory every check_period_s with the sample penalties at
  /// 100 % of the rate limits and no joint margin; any active term is a violation.
  double check_period_s = 0.01;
};

/// The REMANI-style flatness baseline behind the back-end interface
/// (TrajectoryBackEnd: TrajectoryProblem + a front-end WholeBodyPath), as TrajectoryOptimizer:
///  0. the same input checks (CheckTrajectoryProblem);
///  1. warm start: MakeWarmStart's durations and joints, base positions from its path
///     reference at the piece ends, psi_f = the path's last yaw;
///  2. PHR-ALM on the end-effector constraint (eq. (7)) with L-BFGS (Ceres, Wolfe), all the
///     FlatnessObjective terms (no stage 1 path fit, no penalty escalation);
///  3. success = end effector within tolerance and the dense sample check clean.
/// Forward driving only (eta = +1). Optimize is const and thread-safe.
/// The endpoint relief (TrajectoryProblem::exact_prefix_states / exact_suffix_states,
/// EndpointRelief) is checked but ignored: the REMANI-style baseline keeps its full margins
/// everywhere, so a start or goal inside them fails its dense check.
class FlatnessOptimizer : public TrajectoryBackEnd {
 public:
  /// Throws std::invalid_argument for options out of range.
  FlatnessOptimizer(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                    const SignedDistanceField3& arm_field, FlatnessOptimizerOptions options = {});

  /// Never throws for bad input: kInvalidInput with the reason. The summary's
  /// parameterisation is kFlatness (its trajectory: `flatness`, Sampled()).
  BackEndSummary Optimize(const TrajectoryProblem& problem, const WholeBodyPath& initial_path,
                          std::stop_token stop = {}) const override;
  TrajectoryParameterisation parameterisation() const override {
    return TrajectoryParameterisation::kFlatness;
  }

  const FlatnessOptimizerOptions& options() const { return options_; }

 private:
  struct Run;
  /// Builds the warm start (base positions from the path reference), the objective and the
  /// initial decision vector; false (with the summary's status and reason) for a bad path.
  bool Prepare(const WholeBodyPath& initial_path, Run* run) const;
  /// PHR-ALM outer iterations (eq. (7)) until the end effector is within the ALM tolerances,
  /// the outer limit, a stop or the deadline (run->aborted).
  void RunAugmentedLagrangian(Run* run) const;
  /// Evaluates the final iterate, copies it into the summary, runs the dense check and sets
  /// the status and reason.
  void Conclude(Run* run) const;
  /// The dense check of the summary's trajectory: summary->check_violations.
  void Check(const TrajectoryProblem& problem, BackEndSummary* summary) const;

  const Kinematics& kinematics_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  FlatnessOptimizerOptions options_;
  ReachHeights reach_;
};

}  // namespace topay
