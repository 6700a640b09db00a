#pragma once

#include <optional>

#include "core/optimization/trajectory_optimizer.h"
#include "core/planning/front_end_options.h"
#include "core/robot/robot_model.h"
#include "core/validate/trajectory_validator.h"

namespace topay {

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
};

/// Throws std::invalid_argument naming the first option (of the planner's own) out of range.
void CheckWholeBodyPlannerOptions(const WholeBodyPlannerOptions& options);

}  // namespace topay
