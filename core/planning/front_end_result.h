#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/planning/arm_rrt_star.h"
#include "core/planning/base_path.h"
#include "core/planning/discrete_se2.h"
#include "core/planning/goal_candidates.h"
#include "core/planning/goal_clearance.h"
#include "core/planning/topological_path_search.h"
#include "core/planning/whole_body_path.h"

namespace topay {

/// Outcome of one arm-search job (one base path of one goal attempt).
struct ArmJobReport {
  int goal_attempt = 0;        ///< Index of the goal candidate this job planned towards.
  int base_path_index = 0;     ///< Index into that attempt's base paths.
  int homotopy_class = 0;
  BasePathSource source = BasePathSource::kTopologicalPrm;
  ArmRrtStarStatus status = ArmRrtStarStatus::kInvalidInput;
  std::string message;         ///< The RRT*'s message, or why the job did not run.
  ArmRrtStarStats stats;
  bool started = false;        ///< False if it was cancelled before it began.
  double wall_ms = 0.0;        ///< From job start to its end.
  double finished_at_ms = 0.0; ///< Since the start of Plan.
};

/// One whole-body path of the front end with what it was built from.
struct FrontEndPath {
  /// States (one per base layer, consecutive states on adjacent layers), times, cost,
  /// base_path_index (into FrontEndResult::base_paths) and homotopy_class.
  WholeBodyPath path;
  BasePath base_path;
  DiscreteSE2Path base_sequence;  ///< The layers path.states lie on, in order.
  int job = 0;                    ///< Index into FrontEndResult::jobs.
  /// Leading (trailing) states of path that lie in the start's (goal's) exact zone and that
  /// the fields reject: 1 + the index of the last such state from the start (from the end);
  /// 0 when the start (goal) is clear on the fields. The back end relaxes its margins there
  /// (TrajectoryProblem::exact_prefix_states).
  int exact_prefix_states = 0;
  int exact_suffix_states = 0;

  double duration_s() const { return path.times_s.empty() ? 0.0 : path.times_s.back(); }
};

/// Counters and wall-clock timings (steady clock, ms since nothing / since Plan started).
struct FrontEndStats {
  // Goal.
  int num_goal_candidates = 0;
  int num_goal_attempts = 0;
  bool goal_from_hint = false;     ///< The chosen goal came from the hint.
  /// The goal candidates ran out without a base path and the reachable-goal search ran
  /// (FrontEndOptions::reachable_goal_search); its candidates follow the first ones.
  bool used_reachable_goal_search = false;
  /// The goal search's second round ran (FrontEndOptions::goal_retry).
  bool used_goal_retry = false;
  /// What the goal search's clearance function decided (both rounds).
  GoalClearanceTally goal_clearance;
  /// The start (the chosen goal) was rejected by the fields but is exactly clear: it got an
  /// exact zone (ExactZones) and, if the base path search needed one, a base escape move.
  bool start_in_exact_zone = false;
  bool goal_in_exact_zone = false;
  bool start_base_escape = false;
  bool goal_base_escape = false;
  /// The goal candidate kept the start's base pose (GoalCandidate::base_stays): its one base
  /// path is the robot standing still (BasePathSource::kStanding), no search.
  bool standing_base_path = false;
  // Base paths (the goal attempt that produced the result, else the last one).
  int num_prm_nodes = 0;           ///< Guards + connectors.
  int num_raw_paths = 0;           ///< DFS.
  int num_classes_kept = 0;        ///< Topological PRM paths after UVD pruning.
  bool used_fallback_base_clearance = false;  ///< The second, narrower base search ran.
  int num_base_paths = 0;          ///< Including JPS.
  bool jps_ok = false;
  // Arm search, summed over the jobs of every attempt.
  int num_jobs = 0;
  int num_jobs_succeeded = 0;
  std::int64_t rrt_iterations = 0;
  /// Since Plan started, when the first job returned a solution (+infinity if none).
  double time_to_first_solution_ms = std::numeric_limits<double>::infinity();
  /// Per-job RRT* time to first solution (ms), smallest over the successful jobs.
  double rrt_first_solution_ms = std::numeric_limits<double>::infinity();
  // Stage timings (ms), summed over the goal attempts.
  double goal_ms = 0.0;
  double topology_ms = 0.0;
  double discretisation_ms = 0.0;
  double acquisition_ms = 0.0;     ///< Wall time of the parallel arm stage.
  double total_ms = 0.0;
};

/// Why Plan returned no path.
enum class FrontEndStatus {
  kSuccess,
  kInvalidInput,      ///< NaN, wrong joint count, bad pose.
  kStartInvalid,      ///< The start state fails the whole-body validity.
  kNoGoal,            ///< No collision-free whole-body goal state for the target.
  kNoBasePath,        ///< No base path to any goal candidate.
  kNoArmPath,         ///< Base paths, but no arm search succeeded.
  kCancelled,         ///< Stopped by the caller before any path was found.
};
std::string_view ToString(FrontEndStatus status);

struct FrontEndResult {
  FrontEndStatus status = FrontEndStatus::kInvalidInput;
  /// Empty on success; otherwise what failed and where, e.g. "start state: arm collision".
  std::string failure_reason;
  /// Successful whole-body paths, shortest duration first (the authors' code's choice rule),
  /// at most one per arm job: one per base path, or more when its end turns were also tried
  /// the other way round (FrontEndOptions::other_way_turn_min_rad).
  std::vector<FrontEndPath> paths;
  /// The goal state the paths end at (the chosen candidate), and all candidates.
  WholeBodyState goal;
  GoalCandidatesResult goal_candidates;
  /// Base paths of the attempt that produced the result (else the last attempt).
  std::vector<BasePath> base_paths;
  TopologicalPathSearchStats topology;
  /// Every arm job of every attempt, in attempt then base-path order.
  std::vector<ArmJobReport> jobs;
  FrontEndStats stats;

  bool success() const { return !paths.empty(); }
};

}  // namespace topay
