#pragma once

#include <cstdint>
#include <optional>

#include "core/planning/arm_rrt_star.h"
#include "core/planning/arm_dwell.h"
#include "core/planning/base_escape.h"
#include "core/planning/discrete_se2.h"
#include "core/planning/exact_zones.h"
#include "core/planning/goal_candidates.h"
#include "core/planning/topological_path_search.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_ik.h"

namespace topay {

/// The goal search's second round (FrontEndOptions::goal_retry): when the IK finds no goal
/// within its first budget, it searches again with these figures in place of the IK's own
/// (a new seed, more base poses and restarts, a longer time budget) before the front end
/// gives up.
struct GoalRetryOptions {
  bool enabled = true;
  int max_base_candidates = 64;
  int restarts_per_base = 8;
  double time_budget_s = 0.25;
  int max_total_iterations = 100000;
};

/// Options of FrontEnd (paper Sec. III-A, Algorithm 1), Ceres style. Defaults follow the facts
/// sheet's front-end figures where it gives one; departures are stated field by field.
struct FrontEndOptions {
  // ---- Goal ------------------------------------------------------------------------------
  /// Whole-body IK for the goal candidates. Front-end defaults (set by DefaultIkOptions):
  /// max_solutions 3, time_budget_s 0.03 (the hint, when valid, is accepted at once; the
  /// budget bounds the search when it is not).
  WholeBodyIkOptions ik = DefaultIkOptions();
  GoalCandidatesOptions goal;
  /// Goal candidates tried in turn (each: base paths + arm search) until one yields at least
  /// one whole-body path.
  int max_goal_attempts = 2;

  /// Second round of the goal search when the first finds no goal (not when it was stopped).
  GoalRetryOptions goal_retry;

  // ---- Exact zones (a FrontEnd built with an exact checker) --------------------------------
  /// Around a start, or a goal candidate, that the fields reject but the exact scene accepts,
  /// states are checked exactly where the fields reject them (ExactZones: within radius_m of
  /// its base position; the margins are the exact clearances required, which the planner
  /// sets to its validator's), and the base path search starts (ends) at the nearest
  /// position it accepts, reached by a straight move (base_escape).
  ExactZoneOptions exact_zones;
  BaseEscapeOptions base_escape;

  // ---- Base paths ------------------------------------------------------------------------
  /// Topological PRM + JPS (authors' code: 10 ms / 5000 samples, 300 raw paths, 25 kept,
  /// <= 6 classes within 2 x the shortest, JPS appended). mode = kJpsOnly is the Table I
  /// ablation. base_radius_m is overwritten by the model's base cylinder radius, and
  /// clearance_m is raised to the validity's base margin if smaller, so that every base path
  /// passes the arm search's base check.
  /// Front-end departures from the search's own defaults (which follow the 2D field's cell
  /// size): shortcut resampling every 0.05 m and UVD at 0.1 m (the authors' code's map
  /// resolution), so that the fine (0.01 m) base field does not make them 2.5-5x slower.
  TopologicalPathSearchOptions topology = DefaultTopologyOptions();
  /// Clearance (m) beyond the base radius for a second base path search, run when the first
  /// one (at topology.clearance_m, the authors' code's 0.1 m) finds no path or finds the start
  /// or goal closer than that to an obstacle: narrow passages and cluttered corners. It is
  /// raised to the validity's base margin if smaller (so 0 means "as close as the validity
  /// allows"). No second search when it is not below topology.clearance_m.
  double fallback_base_clearance_m = 0.0;
  /// When every goal candidate failed for want of a base path (its base pose lies in a part
  /// of the map the base cannot reach from the start: the far side of a table, a pocket
  /// between furniture), search the IK again without the hint, accepting only base poses in
  /// the start's connected region of the 2D field at the fallback clearance
  /// (BaseReachableRegion), and try up to max_goal_attempts of those. Ours: the paper keeps
  /// the one goal of the task; a user expects the robot to approach the target from a side it
  /// can get to.
  bool reachable_goal_search = true;
  /// Delta l = 1.414 m, turns in place at the vertices.
  DiscreteSE2Options discretisation;
  /// A base path whose turn in place at the start (or at the goal) is at least this large
  /// (rad) gets a second arm job with that turn the other way round (DiscreteSE2Turns; ours,
  /// finding 29's third case: a robot stopped with its arm out over a table and its path
  /// behind it turned half a turn the way that swept the arm through the table, and every
  /// plan failed, where the other way round was clear). 2.5 rad: the other way is at most
  /// 3.8 rad. +infinity: never.
  double other_way_turn_min_rad = 2.5;
  /// A base sequence too short for the arm's move ends with the base standing (ours, finding
  /// 29: a robot stopped next to its goal; arm_dwell.h).
  ArmDwellOptions arm_dwell;
  /// Base limits for the layers' arrival times (they bound the joint steps). Unset: the
  /// model's (the real robot's omega_max 0.9 rad/s); the benchmark sets its own.
  std::optional<BaseLimits> base_limits;

  // ---- Arm search (one job per base path) ------------------------------------------------
  /// Facts sheet: t_smax 0.2 s, goal bias 0.4. Anytime search (stop_at_first_solution =
  /// false, the paper's Algorithm 1): every job keeps improving its path until the
  /// improvement window below closes (it starts at the first solution of any job, reported
  /// through on_first_solution, which the front end sets itself and chains to a caller's),
  /// its t_smax, or its cost lower bound. stop_at_first_solution = true is the reference
  /// code's first-solution exit.
  ArmRrtStarOptions rrt = DefaultRrtOptions();
  /// Field-based whole-body validity (default margins make field-valid states exactly clear).
  WholeBodyValidityOptions validity;
  /// After the first solution of any job, all jobs (that one included) get at most this long
  /// (s) to improve or finish before they are cancelled; cancelled jobs that have a solution
  /// keep their best one (authors' code: ~100 ms in the reference code, not a bound there; here
  /// it is, and smaller, for a 40 ms front-end median). +infinity: wait for all jobs.
  double improvement_window_s = 0.01;
  /// Bound (s) on the whole arm-search stage of one goal attempt, from its start: jobs still
  /// running then are cancelled. Jobs queue when there are more paths than threads.
  double acquisition_budget_s = 0.5;
  /// Worker threads of the front end's TBB arena (base path shortcutting and arm jobs).
  /// 0: TBB's default (all cores).
  int num_threads = 0;
  /// Seed of the random stages of one Plan call: the PRM of goal attempt a gets
  /// DeriveSeed(seed, 2 * a), arm job j of attempt a DeriveSeed(seed, 1000 * (a + 1) + j).
  /// (The IK draws from ik.seed.) The same seed gives the same result as long as no
  /// wall-clock limit cuts a stage short.
  std::uint64_t seed = 1;

  static TopologicalPathSearchOptions DefaultTopologyOptions() {
    TopologicalPathSearchOptions o;
    o.shortcut.resample_step_m = 0.05;
    o.pruning.resolution_m = 0.1;
    return o;
  }
  static WholeBodyIkOptions DefaultIkOptions() {
    WholeBodyIkOptions o;
    o.max_solutions = 3;
    o.time_budget_s = 0.03;
    return o;
  }
  static ArmRrtStarOptions DefaultRrtOptions() {
    ArmRrtStarOptions o;
    o.stop_at_first_solution = false;  // anytime, as the paper's Algorithm 1
    return o;
  }
};

/// Throws std::invalid_argument naming the first option (of the front end's own) out of range.
void CheckFrontEndOptions(const FrontEndOptions& options);

}  // namespace topay
