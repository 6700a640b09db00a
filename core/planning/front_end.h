#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <vector>

#include <Eigen/Geometry>

#include "core/collision/scene_clearance.h"
#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/planning/front_end_options.h"
#include "core/planning/front_end_result.h"
#include "core/planning/parallel_acquisition.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_ik.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// The planner's front end, hierarchical path acquisition (paper Sec. III-A, Algorithm 1):
///  1. goal candidates: whole-body goal states for the end-effector target from the IK
///     (hint first, ranked by base travel and field clearance; goal_candidates.h);
///  2. for a goal candidate: topological base paths on the 2D field from the start base
///     position to the goal's (visibility PRM, DFS, shortcut, UVD pruning) plus a JPS path,
///     or JPS alone (topological_path_search.h);
///  3. each base path discretised into SE(2) layers (DiscreteSE2, start and goal yaw
///     included) and searched by the constrained bidirectional informed RRT* for the arm, one
///     job per path in parallel on a TBB arena (parallel_acquisition.h);
///  4. if no job succeeds, the next goal candidate (up to max_goal_attempts); if none had a
///     base path, goal candidates whose base the start can reach (BaseReachableRegion).
/// Validity everywhere is WholeBodyValidity on the two fields (with its default margins a
/// valid state is exactly clear of the scene the fields were built from). Given an exact
/// checker (the scene, or later the map's voxels), a start or goal candidate the fields
/// reject but the exact scene accepts is valid: it gets an exact zone (ExactZones,
/// FrontEndOptions::exact_zones) in which the fields' rejections are checked again exactly,
/// and the base path search leaves (reaches) it by an escape route (FindBaseEscape: a straight
/// move, or a short route around table legs); the paths say how many of their first and last states needed the
/// exact check (FrontEndPath::exact_prefix_states).
///
/// Cancellation: Plan polls `stop` between stages and passes it (merged with its own
/// deadlines) to the base path search and to every arm job, which poll it every iteration.
///
/// The kinematics (and its model) and both fields must outlive this object. Plan is const and
/// may be called from several threads at once (each call has its own scratch; they share the
/// arena's threads).
class FrontEnd {
 public:
  /// Throws std::invalid_argument for options out of range (naming them).
  /// `exact`, if given, must outlive this object (with its scene).
  FrontEnd(const Kinematics& kinematics, const SignedDistanceField2& base_field,
           const SignedDistanceField3& arm_field, FrontEndOptions options = {},
           const SceneClearanceChecker* exact = nullptr);
  ~FrontEnd();
  FrontEnd(const FrontEnd&) = delete;
  FrontEnd& operator=(const FrontEnd&) = delete;

  /// Whole-body paths from `start` to a state whose end effector is at X_WE_target (within
  /// the IK's tolerances, 1 mm / 0.01 rad by default). `hint`: a whole-body goal state tried
  /// first. Never throws for bad input: an empty result whose status and failure_reason say
  /// what was wrong (NaN, wrong joint count, start invalid, no goal, no base path, no arm
  /// path, cancelled).
  FrontEndResult Plan(const WholeBodyState& start, const Eigen::Isometry3d& X_WE_target,
                      const std::optional<WholeBodyState>& hint = std::nullopt,
                      std::stop_token stop = {}) const;

  const FrontEndOptions& options() const { return options_; }
  const WholeBodyValidity& validity() const { return validity_; }

 private:
  struct Arena;
  struct PlanContext;

  void PlanInArena(PlanContext* context) const;
  /// Empty if the start is usable (on the fields, or exactly inside a new exact zone, which
  /// it records in the context), else the reason it is not.
  std::string CheckStart(PlanContext* context) const;
  /// The goal search (FindGoalCandidates with GoalClearance), with its second round.
  GoalCandidatesResult SearchGoals(const WholeBodyState* hint,
                                   const std::function<bool(const WholeBodyState&)>& admit,
                                   PlanContext* context) const;
  /// validity_ with the exact zones of this attempt: the start's, and the goal's if the
  /// fields reject it.
  /// The exact zones of one goal attempt: the start's and the goal's, each where the fields
  /// reject the state or its base is closer to an obstacle than the base path search keeps
  /// (BaseIsTight).
  WholeBodyValidity AttemptValidity(const GoalCandidate& goal, PlanContext* context) const;
  /// The base's field distance is below its radius + the base path search's clearance.
  bool BaseIsTight(const WholeBodyState& state) const;
  bool FindGoals(PlanContext* context) const;
  /// Tries goal candidates [first, first + max_goal_attempts) in turn. True on success.
  bool AttemptGoals(int first, PlanContext* context) const;
  /// More goal candidates, without the hint, whose base lies in the start's reachable region
  /// of the 2D field (FrontEndOptions::reachable_goal_search); appended to the result's.
  /// False if there are none.
  bool FindReachableGoals(PlanContext* context) const;
  /// One goal attempt: base paths, layers, arm jobs. True if a path was found.
  bool AttemptGoal(int attempt, PlanContext* context) const;
  // The steps of AttemptGoal.
  /// Topological base paths to the goal's base (again at the fallback clearance if none);
  /// records the search's figures in the result.
  TopologicalPathSearchResult SearchBasePaths(int attempt, const GoalCandidate& goal,
                                              const WholeBodyValidity& validity,
                                              PlanContext* context) const;
  /// One base path search at `clearance_m`, from and to the escape positions of a start or
  /// goal the field rejects there (in an exact zone), the escape moves put back into the
  /// paths.
  TopologicalPathSearchResult SearchBasePathsAt(double clearance_m, const GoalCandidate& goal,
                                                const TopologicalPathSearchOptions& topology,
                                                const WholeBodyValidity& validity,
                                                PlanContext* context) const;
  /// One arm job per base path, shortest first, each with its DiscreteSE2 layers; a path
  /// with a turn in place at its start or goal of at least other_way_turn_min_rad is followed
  /// by a job with that turn the other way round.
  std::vector<ArmJob> MakeArmJobs(int attempt, const GoalCandidate& goal,
                                  const TopologicalPathSearchResult& search,
                                  PlanContext* context) const;
  /// The layers of `path` towards `goal` (DiscreteSE2 with `turns`, then AddArmDwell) in
  /// *sequence; returns the error that stopped it ("" if none).
  std::string Discretise(const BasePath& path, const GoalCandidate& goal, const BaseLimits& limits,
                         const DiscreteSE2Turns& turns, const PlanContext& context,
                         DiscreteSE2Path* sequence) const;
  /// The parallel arm RRT* stage on the jobs; records its figures in the result's stats.
  ParallelAcquisitionResult AcquireArmPaths(int attempt, const GoalCandidate& goal,
                                            const std::vector<ArmJob>& jobs,
                                            const WholeBodyValidity& validity,
                                            PlanContext* context) const;

  const Kinematics& kinematics_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  FrontEndOptions options_;
  WholeBodyValidity validity_;
  WholeBodyIk ik_;
  WholeBodyIk ik_retry_;  ///< ik_ with FrontEndOptions::goal_retry's figures.
  const SceneClearanceChecker* exact_;
  std::unique_ptr<Arena> arena_;
};

}  // namespace topay
