#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace topay {

/// One tree of the layered bidirectional RRT* (core/planning/arm_rrt_star.h): nodes (layer, q)
/// rooted on one layer, every edge going from a node on layer l to a child on layer
/// l + direction(). Keeps nodes bucketed by layer and children lists so a rewire can update
/// the costs of a whole subtree. Costs use the metric given to the queries (weights w).
class LayeredArmTree {
 public:
  struct Node {
    int layer = 0;
    Eigen::VectorXd q_rad;
    int parent = -1;
    double cost = 0.0;  ///< Cost-to-root along the tree.
    std::vector<int> children;
  };

  /// direction: +1 (grows to higher layers) or -1.
  LayeredArmTree(int num_layers, int root_layer, const Eigen::VectorXd& q_root, int direction,
                 const Eigen::VectorXd& weights);

  int direction() const { return direction_; }
  int root_layer() const { return nodes_.front().layer; }
  int size() const { return static_cast<int>(nodes_.size()); }
  const Node& node(int id) const { return nodes_[static_cast<std::size_t>(id)]; }
  const std::vector<int>& nodes_on_layer(int layer) const {
    return by_layer_[static_cast<std::size_t>(layer)];
  }

  /// |a - b|_w = sqrt(sum_i w_i (a_i - b_i)^2).
  double Distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;

  /// The node nearest to q (metric |.|_w) among the nodes on layers strictly behind `layer`
  /// (i.e. l with (layer - l) * direction() >= 1); -1 if there is none.
  int Nearest(int layer, const Eigen::VectorXd& q) const;

  /// Up to max_count (distance, id) pairs of nodes on `layer` within `radius` of q, nearest
  /// first, into *out (cleared first).
  void Near(int layer, const Eigen::VectorXd& q, double radius, int max_count,
            std::vector<std::pair<double, int>>* out) const;

  /// Adds a node on parent's next layer with cost parent.cost + |q - parent.q|_w; its id.
  int Add(int parent, const Eigen::VectorXd& q_rad);

  /// Makes `new_parent` the parent of `id` and updates the costs of id's subtree.
  void Reparent(int id, int new_parent);

  /// Node ids from the root to `id`, root first.
  void PathToRoot(int id, std::vector<int>* ids_root_first) const;

 private:
  void ShiftSubtreeCost(int id, double delta);

  int direction_;
  Eigen::VectorXd sqrt_weights_;
  std::vector<Node> nodes_;
  std::vector<std::vector<int>> by_layer_;
};

}  // namespace topay
