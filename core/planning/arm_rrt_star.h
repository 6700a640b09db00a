#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <limits>
#include <stop_token>
#include <string>

#include "core/planning/discrete_se2.h"
#include "core/planning/whole_body_path.h"
#include "core/planning/whole_body_validity.h"

namespace topay {

/// Options of PlanArmRrtStar (paper Algorithm 1, the inner loop for one base path).
struct ArmRrtStarOptions {
  /// t_smax: wall-clock budget (s) of the anytime search (authors' code: 0.2 s). The search
  /// also ends at max_iterations, on cancellation, or when the cost reaches its lower bound.
  double time_budget_s = 0.2;
  /// Iteration cap (0: none). With a cap and a budget that is not reached, the result is a
  /// pure function of the inputs and the seed.
  std::int64_t max_iterations = 0;
  /// End at the first solution (the reference code's behaviour) instead of improving it.
  bool stop_at_first_solution = false;
  /// Probability that a sample is the other tree's root (authors' code: 0.4).
  double goal_bias = 0.4;
  /// Probability that a sample (when not the goal) is the robot's stowed configuration
  /// (RobotModel::stow_q_rad, clamped to the layer's velocity-reachable box) on a random layer.
  /// Ours, not the paper's: passages where only a folded arm fits (under table tops, between
  /// close obstacles) are a thin set for uniform samples. On 100 Tables large tasks it cut the
  /// arm stage's failures from 13 to 4 and its p95 from 466 to 126 ms (docs/benchmarks.md).
  /// No effect for a model without stow_q.
  double stow_bias = 0.25;
  /// Link and Rewire consider tree nodes on the adjacent layer within this cost-metric
  /// distance (weighted joint-space norm, rad) of the new node.
  double rewire_radius_rad = 1.5;
  /// At most this many nearest neighbours (per Link or Rewire) are tried.
  int max_neighbours = 16;
  /// Weights w_i of the cost metric |dq|_w = sqrt(sum_i w_i dq_i^2). Empty: all 1.
  Eigen::VectorXd joint_weights;
  /// Informed sampling: draws from the prolate hyperspheroid rejected (outside the joint
  /// limits or the velocity-reachable box of the layer) before falling back to a uniform draw.
  int max_informed_draws = 64;
  /// Node cap over both trees; growth stops there (the search continues to rewire/connect).
  int max_nodes = 50000;
  std::uint64_t seed = 1;
  /// Called once per run, with the solution's cost (weighted joint-space length, rad), when
  /// c_max first becomes finite: the moment a first solution exists, before the anytime
  /// improvement goes on. Empty: not called. Thread-safety: it runs synchronously on the
  /// thread that called PlanArmRrtStar, inside the search loop, so it must be quick and must
  /// not throw; when several searches run in parallel and share state through it, that
  /// state must be synchronised by the callback (a mutex or atomics). A run that ends before
  /// a solution exists never calls it.
  std::function<void(double cost)> on_first_solution;
};

/// Empty if the options are usable, else the first option out of range and its rule (the
/// search returns kInvalidInput with it; the planner YAML loader throws it as a ConfigError).
/// num_joints < 0: joint_weights is checked for values only, not for its size.
std::string CheckArmRrtStarOptions(const ArmRrtStarOptions& options, int num_joints = -1);

/// Why PlanArmRrtStar stopped / failed.
enum class ArmRrtStarStatus {
  kSuccess,
  kInvalidInput,     ///< Empty base sequence, wrong joint count, NaN, bad options.
  kStartInvalid,     ///< The start state fails WholeBodyValidity (reason in message).
  kGoalInvalid,      ///< The goal state fails WholeBodyValidity.
  kBasePathInvalid,  ///< A base layer or base edge fails the 2D field check.
  kNoSolution,       ///< Budget or iteration cap exhausted without connecting the trees.
  kCancelled,        ///< stop_token fired before any solution was found.
};
std::string_view ToString(ArmRrtStarStatus status);

/// Statistics of one PlanArmRrtStar run.
struct ArmRrtStarStats {
  std::int64_t iterations = 0;
  int nodes_start_tree = 0;
  int nodes_goal_tree = 0;
  int num_solutions = 0;  ///< Times c_max improved.
  double time_to_first_solution_s = std::numeric_limits<double>::infinity();
  double first_cost = std::numeric_limits<double>::infinity();
  double final_cost = std::numeric_limits<double>::infinity();
  /// Lower bound of the cost: |q_goal - q_start|_w.
  double cost_lower_bound = 0.0;
  double elapsed_s = 0.0;
  bool cancelled = false;
};

struct ArmRrtStarResult {
  ArmRrtStarStatus status = ArmRrtStarStatus::kInvalidInput;
  /// Empty on success; otherwise what failed, e.g. "start state: arm collision".
  std::string message;
  /// On success: one state per layer, start layer first, goal layer last (consecutive states
  /// on adjacent layers); times_s = the layers' time_s; cost = sum of |dq|_w along it.
  /// base_path_index and homotopy_class are left at -1 for the caller.
  WholeBodyPath path;
  ArmRrtStarStats stats;

  bool success() const { return status == ArmRrtStarStatus::kSuccess; }
};

/// Constrained bidirectional informed RRT* for the arm along a discrete base sequence (paper
/// Sec. III-A, Algorithm 1). Nodes are (layer, q) with the base fixed by the layer; tree A
/// grows from (0, q_start), tree B from (last layer, q_goal), each only towards the other's
/// root layer one layer per edge, with joint steps |dq_i| <= qd_max_i * step time of the layer
/// transition. Cost of a path: sum over its edges of |q_{k+1} - q_k|_w. Details (Sample,
/// Nearest, Steer, TrySwap, Link/Rewire, TryConnect, TryUpdateCost, MergeTree, informed set)
/// are documented in arm_rrt_star.cc. Checks `stop` every iteration and inside long inner
/// loops. If the search is cancelled or runs out of budget after a solution was found, the
/// best solution is returned (status kSuccess, stats.cancelled tells).
/// Never throws for bad input: status kInvalidInput with a message.
ArmRrtStarResult PlanArmRrtStar(const DiscreteSE2Path& base_sequence,
                                const Eigen::VectorXd& q_start_rad,
                                const Eigen::VectorXd& q_goal_rad,
                                const WholeBodyValidity& validity,
                                const ArmRrtStarOptions& options = {}, std::stop_token stop = {});

}  // namespace topay
