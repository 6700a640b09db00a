#pragma once

#include <optional>

#include "core/optimization/trajectory_optimizer.h"
#include "core/planning/front_end_options.h"
#include "core/planning/lead_in.h"
#include "core/robot/robot_model.h"
#include "core/validate/trajectory_validator.h"

namespace topay {

/// Further planning rounds after a round that ends without a validated trajectory (ours: the
/// paper plans once per call). Round r > 0 runs the front end again with seeds derived from r
/// (other IK restarts and base poses, other PRM samples and arm RRT* trees, so other paths),
/// then optimizes and validates as before; after each round in which the validator rejected
/// an optimizer success, the back end's clearance margins (SamplePenaltyOptions::
/// base_field_margin_m, arm_field_margin_m) grow by clearance_step_m. Every round runs under
/// the plan's one time limit, so a retry only ever uses time the plan had left. Retried:
/// no goal, no base path, no arm path (with a larger arm RRT* budget), no validated trajectory; never an invalid input, a
/// refused start, a cancelled plan or one the time limit ended.
struct PlanRetryOptions {
  /// Rounds in all, the first included (1: plan once, as the paper). >= 1.
  int max_rounds = 3;
  /// A further round starts only with at least this much (s) of the time limit left. >= 0.
  double min_time_left_s = 0.3;
  /// Added to the back end's clearance margins (m) per earlier round with a validator
  /// rejection. >= 0.
  double clearance_step_m = 0.005;
  /// A round that may be followed by another ends, at the latest, when it has used this share
  /// of the time left when it began (with a 3 s limit: 2.25 s, then 0.56 s, then the rest);
  /// the last round may use all that is left. A round whose front end is done keeps the
  /// plan's time when what its share would leave could not hold another round (a front end
  /// as long as its own, then min_time_left_s; RoundKeepsThePlanTime). The optimizations of
  /// long detours past tight ends often converge after 1.4-2.2 s: 0.6 cut them (tight Tables
  /// cells, 286 -> 292 of 300 tasks with 0.75; docs/benchmarks.md, "Sixth session"), while an
  /// optimizer that has gone astray is still cut in time for another path or warm start.
  /// In (0, 1].
  double round_time_share = 0.75;
  /// Round r's arm RRT* gets growth^r times the configured budget (its time_budget_s and,
  /// if set, max_iterations): an arm path that did not connect within one budget at a tight
  /// end often connects with a larger one, and a retry only runs on time the plan had left.
  /// >= 1 (1: every round the same budget).
  double arm_budget_growth = 2.0;
  /// Rounds after the first, from a start at rest, start the optimizer from a slower warm
  /// start: its trapezoidal profiles at optimizer.warm_start.rate_fraction x this of the rate
  /// limits (more time, hence more pieces; a moving start keeps the configured warm start,
  /// whose profile must begin at the start's speed). An optimizer that did not converge from
  /// the warm start at the full limits (rates and clearances short together near a tight end)
  /// often converges from the slower one: on the tight Tables cells, 7 of 12 such failures
  /// with 0.6, against 4 of 12 with the same warm start again (docs/benchmarks.md, "Fifth
  /// session"). In (0, 1] (1: the same warm start every round).
  double warm_start_slowdown = 0.6;
};

/// Options of WholeBodyPlanner (paper Sec. III), Ceres style.
struct WholeBodyPlannerOptions {
  /// Path acquisition (core/planning/front_end_options.h). Its base_limits are overwritten by
  /// base_limits below when that is set, so that the layers' times, the optimizer and the
  /// validator use one set of limits.
  FrontEndOptions front_end;
  /// Trajectory optimization of each candidate path (core/optimization).
  TrajectoryOptimizerOptions optimizer;
  /// The independent check of every success (exact boxes, 10 ms samples, limits + 1 %).
  TrajectoryValidatorOptions validator;
  /// A moving start (issue 18): the braking lead-in along the current heading that the
  /// whole-body path begins with (core/planning/lead_in.h; defaults there).
  LeadInOptions lead_in;
  /// Base limits of the whole plan. Unset: the robot model's (the real robot's
  /// omega_max 0.9 rad/s); the benchmark sets the paper's simulation limits.
  std::optional<BaseLimits> base_limits;

  /// Early termination (issue: back end, item 5): after the first validated success, the
  /// other candidates get at most this long (s) to finish; then they are cancelled
  /// cooperatively (the optimizer polls its stop token in every objective evaluation) and
  /// the shortest-duration validated trajectory is returned.
  double early_termination_window_s = 0.05;
  /// The "Sequential" ablation: optimize every candidate, one after another on the calling
  /// thread (its sample chunks too), no early termination.
  bool sequential = false;
  /// Threads of the optimization stage: candidates run on up to this many workers (more
  /// wait for a free one), and a thread without a candidate helps the running optimizers'
  /// sample chunks (TrajectoryObjectiveOptions::sample_chunks). 0: the hardware's thread
  /// count.
  int num_threads = 0;
  /// Bound (s) on one Plan call, every stage included (front end, every optimization, the
  /// validation; in PlanInScene also the start check and the map build): whatever is still
  /// running then is cancelled cooperatively, and the plan fails with status kTimeLimit and
  /// the stage (WholeBodyPlanResult::stopped_stage) unless a validated trajectory exists.
  double time_limit_s = 3.0;
  /// At most this many front-end paths are optimized (shortest duration first).
  int max_candidates = 8;
  /// Further rounds after a round without a validated trajectory.
  PlanRetryOptions retry;
};

/// The front end of retry round r (PlanRetryOptions): round 0 as given; round r > 0 with every
/// seed derived from r (DeriveSeed(seed, salt + r): other IK restarts and base poses, PRM
/// samples, RRT* trees) and the arm RRT*'s time budget and iteration cap (if set) times
/// arm_budget_growth^r.
FrontEndOptions RetryRoundFrontEnd(const FrontEndOptions& front_end, const PlanRetryOptions& retry,
                                   int round);

/// Throws std::invalid_argument naming the first option (of the planner's own) out of range.
void CheckWholeBodyPlannerOptions(const WholeBodyPlannerOptions& options);

}  // namespace topay
