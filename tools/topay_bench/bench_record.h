#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "core/planner/whole_body_plan_result.h"
#include "core/robot/whole_body_state.h"
#include "sim/scenes/task_tightness.h"
#include "tools/topay_bench/failure_category.h"
#include "tools/topay_bench/sensed_map_figures.h"
#include "tools/topay_plan/trajectory_record.h"

namespace topay::bench {

/// The work of the optimizer run that produced the chosen trajectory (counts only, so that a
/// deterministic run repeats them exactly).
struct OptimizerWork {
  int num_pieces = 0;
  int stage1_iterations = 0;   ///< L-BFGS iterations of the path fit.
  int stage2_iterations = 0;   ///< L-BFGS iterations over all ALM outer iterations.
  int outer_iterations = 0;    ///< ALM outer iterations.
  int evaluations = 0;         ///< Objective evaluations, both stages.
  int penalty_escalations = 0;
};

/// One task run by one method: one line of tasks.jsonl (bench_record_json.h).
struct BenchRecord {
  // The task.
  int task = 0;                  ///< Index i in [0, tasks).
  std::uint64_t task_seed = 0;   ///< DeriveSeed(S, i).
  std::uint64_t scene_seed = 0;  ///< The generated scene's seed.
  std::string scene;             ///< "cuboids" | "tables".
  std::string range;             ///< "small" | "medium" | "large".
  bool tight = false;            ///< The run's tasks are tight (TaskTightness::kTight).
  WholeBodyState start;
  WholeBodyState goal_hint;  ///< The task's generating goal state.
  bool used_hint = false;    ///< goal_hint was passed to the planner.
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();  ///< End-effector target.
  double base_distance_m = 0.0;  ///< Straight line between start and goal base positions.
  /// No motion of the rigid lower body takes the base from the start to any position from
  /// which the arm could reach the target (CertifyTargetUnreachable in
  /// core/planning/base_reachability.h): no planner can solve the task. Counted as a failure like
  /// any other, and reported apart.
  bool base_unreachable = false;
  /// A tight task's record of its ends (PlanningTask::tight); unset for an open task or one
  /// that could not be generated.
  std::optional<TightTaskInfo> tight_info;

  // The method and its outcome.
  std::string method;          ///< BenchMethodName.
  int order = 0;               ///< Position of the method in this task's rotation (0: first).
  bool success = false;        ///< A validated trajectory within the time limit.
  std::string status;          ///< ToString(PlanStatus); "time_limit" for a late success;
                               ///< "generation_failed" when the task could not be generated.
  std::string failure_reason;  ///< Empty on success.
  FailureCategory failure = FailureCategory::kNone;  ///< kNone on success.

  // Figures.
  PlanTimings timings;  ///< ms; total_ms is T.P.
  double map_ms = 0.0;  ///< Distance fields of the task (shared by its methods; not in T.P.).
  /// A run on a sensed map (method "<name>@sensed"): how it was made (map_ms is then the
  /// mapping plus the fields). Unset for a run on the exact scene.
  std::optional<SensedMapFigures> sensed;
  /// Trajectory duration T.D. (s); NaN without a trajectory.
  double duration_s = std::numeric_limits<double>::quiet_NaN();
  int num_candidates = 0;  ///< Paths given to the back end.
  int num_paths = 0;       ///< Whole-body paths of the front end.
  int num_classes = 0;     ///< Topological classes kept (PRM paths after pruning).
  int num_base_paths = 0;  ///< Base paths, JPS included.
  int plan_rounds = 1;     ///< Planning rounds run (WholeBodyPlanResult::rounds).
  /// The validator's figures of the chosen trajectory (unset: none).
  std::optional<plan::TrajectoryValidationFigures> validation;
  /// The optimizer's work on the chosen trajectory (unset: none).
  std::optional<OptimizerWork> optimizer;

  double tp_ms() const { return timings.total_ms; }
  /// CellName(scene, range, tight).
  std::string cell() const;
};

/// The benchmark cell of a run: "<scene> <range>", with " tight" for tight tasks, e.g.
/// "tables medium tight".
std::string CellName(const std::string& scene, const std::string& range, bool tight);

/// Fills the outcome and figures of *record (the task fields are the caller's) from a plan:
/// success, status, reason, failure category (ClassifyPlanFailure), timings, duration, counts
/// and validation. A validated plan whose T.P. exceeds time_limit_ms is a failure: status
/// "time_limit", category kTimeLimit, reason "time limit: T.P. <x> ms > <L> ms" (its figures
/// are kept).
void FillOutcome(const WholeBodyPlanResult& plan, double time_limit_ms, BenchRecord* record);

}  // namespace topay::bench
