#pragma once

// Internal to PlanArmRrtStar (core/planning/arm_rrt_star.h): the search state of one run.
// Not a public API; use PlanArmRrtStar.
//
// How paper Algorithm 1 maps onto the layered search (one base path):
//  * Trees. trees_[0] grows from (layer 0, q_start) towards higher layers, trees_[1] from
//    (last layer, q_goal) towards lower ones. Every edge joins adjacent layers, so any path
//    visits each layer once and consecutive states differ by exactly one layer.
//  * TrySwap: the tree with fewer nodes becomes T_a (balanced growth, as RRT-Connect's swap).
//  * Sample(P_b, c_max): with probability goal_bias the root of T_b (it is a node of T_b);
//    otherwise a layer uniform among those strictly between the two roots and q uniform in the
//    layer's feasible box: joint limits intersected with the set reachable at the joint speed
//    limits from q_start by the layer's time and from q_goal in the remaining time. Once c_max
//    is finite, q is drawn from the informed set (InformedJointSampler) and kept only if it
//    lies in that box (else, after max_informed_draws, a uniform box draw).
//  * Nearest(T, n_r): the node of T nearest to q_r (|.|_w) on a layer strictly behind n_r's.
//  * Steer(n_n, n_r): one layer towards n_r, q moving by (q_r - q_n) / (layer gap), scaled
//    down uniformly if any |dq_i| exceeds qd_max_i * (step time of the layer transition). It
//    reaches n_r exactly when the gap is 1 and no scaling was needed. States landing on the
//    other tree's root layer other than the root itself are rejected (dead ends).
//  * IsInvalid(n_s): the edge n_n -> n_s fails WholeBodyValidity::CheckEdge (arm parts; the
//    base path is checked once up front).
//  * "n_s in T_b": Steer reached a node of T_b exactly. TryUpdateCost then records the bridge
//    (n_n, n_s) with cost Cost(n_n) + Heu(n_n, n_s) + Cost(n_s) and lowers c_max; the first
//    time c_max becomes finite it calls options.on_first_solution.
//  * JustExpand(n_s): n_s is a new state (samples are never nodes of T_a, so the paper's
//    second branch, a cheaper route to an existing node, is what Rewire does). Link picks the
//    cheapest valid parent among T_a's nodes within rewire_radius_rad on the layer behind
//    (RRT* ChooseParent); Rewire re-parents T_a's nodes on the layer ahead within the radius
//    when reaching them through n_s is cheaper and the edge is valid.
//  * TryConnect(n_os, T_a): RRT-Connect's greedy extension of T_b from n_os towards n_s, one
//    layer at a time, until it lands on n_s (TryUpdateCost) or is blocked or clipped.
//  * MergeTree / GetPath: the best bridge (costs re-evaluated, since rewiring only lowers
//    them) joins root-to-node of trees_[0] with node-to-root of trees_[1].
//  * Cost: sum over edges of |q_{k+1} - q_k|_w (weighted joint-space length). Heu(a, b) =
//    |q_b - q_a|_w. Lower bound: |q_goal - q_start|_w (the search ends when it is reached).

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "core/common/stopwatch.h"
#include "core/common/random.h"
#include "core/planning/arm_rrt_star.h"
#include "core/planning/discrete_se2.h"
#include "core/planning/informed_joint_sampler.h"
#include "core/planning/layered_arm_tree.h"
#include "core/planning/whole_body_validity.h"

namespace topay {

/// A connection between the trees: an edge from a start-tree node to a goal-tree node.
struct RrtBridge {
  int start_node = -1;  ///< Node of trees_[0].
  int goal_node = -1;   ///< Node of trees_[1], on the layer after start_node's.
};

/// The target of a Steer: a layer and q, and whether it is a node of some tree.
struct RrtTarget {
  int layer = 0;
  Eigen::VectorXd q_rad;
  int tree = -1;  ///< Tree holding it as node `node`, or -1 for a free sample.
  int node = -1;
};

/// One run of the constrained bidirectional informed RRT* over a base sequence (see above).
class LayeredRrtSearch {
 public:
  /// All references must outlive this object; inputs are assumed checked by PlanArmRrtStar.
  LayeredRrtSearch(const DiscreteSE2Path& base, const Eigen::VectorXd& q_start,
                   const Eigen::VectorXd& q_goal, const WholeBodyValidity& validity,
                   const ArmRrtStarOptions& options, const Eigen::VectorXd& weights,
                   std::stop_token stop);

  /// Runs until the budget, the iteration cap, cancellation or the cost bound; the result.
  ArmRrtStarResult Run();

 private:
  void ComputeLayerBoxes(const Eigen::VectorXd& q_start, const Eigen::VectorXd& q_goal);
  bool Interrupted() const;
  void Iterate();
  RrtTarget Sample(int a);
  void SampleQ(int layer, Eigen::VectorXd* q);
  std::optional<Eigen::VectorXd> Steer(int tree, int from, const RrtTarget& target,
                                       bool* reached) const;
  bool EdgeFeasible(int tree, int from, const Eigen::VectorXd& q_to);
  bool EdgeValid(int layer_a, const Eigen::VectorXd& q_a, int layer_b, const Eigen::VectorXd& q_b);
  int Link(int tree, int nearest, const Eigen::VectorXd& q);
  void Rewire(int tree, int id);
  void TryUpdateCost(int tree, int node_in_tree, int other_node);
  void TryConnect(int b, int from, const RrtTarget& target);
  /// Extends tree `t` from `from` towards `target` once; returns the new node, -1 if blocked.
  int ExtendOnce(int t, int from, const RrtTarget& target, bool* connected);
  double BridgeCost(const RrtBridge& bridge) const;
  void RefreshBestCost();
  ArmRrtStarResult Finish(ArmRrtStarStatus no_solution_status, std::string message);

  const DiscreteSE2Path& base_;
  const WholeBodyValidity& validity_;
  const ArmRrtStarOptions& options_;
  std::stop_token stop_;
  Stopwatch watch_;  ///< Since construction: the time budget and the stats.
  Rng rng_;
  InformedJointSampler sampler_;
  WholeBodyValidityWorkspace workspace_;
  LayeredArmTree trees_[2];
  Eigen::VectorXd qd_max_;
  std::vector<Eigen::VectorXd> box_low_, box_high_;  ///< Per-layer feasible q box.
  std::vector<RrtBridge> bridges_;
  double c_max_ = std::numeric_limits<double>::infinity();
  int a_ = 0;  ///< Index of T_a in trees_.
  ArmRrtStarStats stats_;
  std::vector<std::pair<double, int>> near_;
  WholeBodyState edge_a_, edge_b_;
};

}  // namespace topay
